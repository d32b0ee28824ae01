# The paper's figures (issue 4): docs/figures/fig05.png ... fig13.png (+ PDF)
# and the numbers of docs/PAPER.md.
#
#   make figures    build ./impact and build/contact_update, run every deck of
#                   input/paper/ (two at a time; results in out/paper/), run
#                   the contact-update experiment, draw postproc/fig*.gp and
#                   write docs/PAPER.md from docs/PAPER.md.in
#                   (tools/paper-numbers). About 2 minutes on 2 cores.

CONTACT_UPDATE := $(BUILD)/contact_update
FIG_JOBS       ?= 2

.PHONY: figures

$(CONTACT_UPDATE): tools/contact_update.f90 $(LIB)
	$(FC_ALL) $< $(LIB) $(LAPACK) -o $@
