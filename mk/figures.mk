# The paper's figures: $(DOCS_DIR)/figures/fig05.png ... fig13.png,
# fig06_converged.png, fig09_10_converged.png (and .pdf) and the numbers of
# $(DOCS_DIR)/PAPER.md. DOCS_DIR (the top Makefile) is out/docs by default:
# the checkout is left as it was; make docs sets DOCS_DIR=docs, the
# published docs/PAPER.md and docs/figures/.
#
#   make figures       build ./impact; run every deck of input/paper/ (and
#                      tolerance/, converged/), and every deck of
#                      input/paper/update/ twice (below),
#                      FIG_JOBS at a time (results and logs in out/paper/);
#                      draw postproc/figNN.gp into $(DOCS_DIR)/figures/;
#                      write $(DOCS_DIR)/PAPER.md: docs/PAPER.md with its
#                      numbers filled in (tools/paper-numbers --template;
#                      in place when DOCS_DIR is docs).
#                      3 to 5 minutes on 2 cores (about 4.5 minutes of CPU,
#                      half of it the 24 x 36 meshes of input/paper/ and
#                      converged/); a rerun redoes only the runs whose deck
#                      or program changed.
#   make figures-clean remove out/paper/ (the next `make figures` reruns all)
#
# The experiment of docs/PAPER.md on the update of the assumed contact
# force runs each deck of input/paper/update/ with the paper's literal
# F_assum <- F_cont (./impact --set analysis.force_update=plain, results
# <deck>_fixed_*) and with this code's bracketed update (<deck>_bracket_*).
# A plain run that diverges stops with exit status 1 and the summary's
# status 'diverged at step N': that is its result, not a failure.
#
# input/paper/strength/ holds Fig. 9 and 10's scenes, linear and
# nonlinear, the paper's model and the converged one, with &strength: the
# ply stresses and Hashin's index of docs/PAPER.md, "Ply stresses"; their
# damage maps (postproc/damage_map.gp, over tools/damage-map and h5py) are
# $(DOCS_DIR)/figures/damage_fig09_simply_supported.png and damage_fig10_clamped.png.
#
# input/paper/converged/ holds the scenes of Fig. 6 (mesh study), 9 and 10
# with the converged model (MITC9 shear, Hertz contact load; docs/PAPER.md,
# "With a converged model"); results in out/paper/converged/. Beside them the
# paper's model on finer meshes than the paper's (input/paper/*_12x18.nml,
# *_24x36.nml). Both are drawn by postproc/fig06_converged.gp and
# fig09_10_converged.gp.

FIG_JOBS       ?= 2
FIG_OUT        := out/paper
FIG_NUMBERS    := 05 06 07 08 09 10 11 12 13 06_converged 09_10_converged
FIG_SCRIPTS    := $(patsubst %,postproc/fig%.gp,$(FIG_NUMBERS))

# the full-plate and long runs first (the 24 x 36 meshes, then the full
# plates), so that two jobs finish together
FIG_LONG       := input/paper/fig06_24x36.nml input/paper/converged/fig06_24x36.nml \
                  input/paper/fig10_clamped_linear_24x36.nml \
                  input/paper/converged/fig10_clamped_linear_24x36.nml \
                  $(sort $(wildcard input/paper/fig05_full_*.nml))
FIG_DECKS      := $(FIG_LONG) \
                  $(filter-out $(FIG_LONG),$(sort $(wildcard input/paper/*.nml))) \
                  $(sort $(wildcard input/paper/tolerance/*.nml)) \
                  $(filter-out $(FIG_LONG),$(sort $(wildcard input/paper/converged/*.nml))) \
                  $(sort $(wildcard input/paper/strength/*.nml))
FIG_RUNS       := $(patsubst input/paper/%.nml,$(FIG_OUT)/%_summary.dat,$(FIG_DECKS))
UPDATE_DECKS   := $(sort $(wildcard input/paper/update/*.nml))
UPDATE_RUNS    := $(foreach u,fixed bracket,\
                    $(patsubst input/paper/update/%.nml,$(FIG_OUT)/update/%_$(u)_summary.dat,$(UPDATE_DECKS)))

.PHONY: figures figures-runs figures-clean

FIG_DIR        = $(DOCS_DIR)/figures

figures: setup impact
	@$(MAKE) --no-print-directory -j$(FIG_JOBS) figures-runs
	@mkdir -p '$(FIG_DIR)'
	@for n in $(FIG_NUMBERS); do \
	    for fmt in png pdf; do \
	        gnuplot -e "fmt='$$fmt'; run='$(FIG_OUT)'; figdir='$(FIG_DIR)'" postproc/fig$$n.gp || exit 1; \
	    done; echo "figure written: $(FIG_DIR)/fig$$n.png, .pdf"; \
	done
	@for s in fig09_simply_supported fig10_clamped; do \
	    gnuplot -e "prefix='$(FIG_OUT)/strength/converged_$${s}_nonlinear'; out='$(FIG_DIR)/damage_$${s}.png'" \
	        postproc/damage_map.gp || exit 1; \
	done
	python3 tools/paper-numbers --runs $(FIG_OUT) --template docs/PAPER.md '$(DOCS_DIR)/PAPER.md'
	@echo 'make figures: wrote $(DOCS_DIR)/PAPER.md and $(FIG_DIR)/ (runs in $(FIG_OUT)/)'

figures-runs: $(FIG_RUNS) $(UPDATE_RUNS)

# one ./impact run per deck; its prefix is out/paper/<deck name> (a run that
# fails leaves its log and no summary, and stops make)
$(FIG_OUT)/%_summary.dat: input/paper/%.nml impact
	@mkdir -p $(dir $@)
	@echo "impact $<"
	@./impact $< > $(FIG_OUT)/$*.log 2>&1 || { rm -f $@; tail -3 $(FIG_OUT)/$*.log; exit 1; }

# the update experiment: ./impact with force_update set, its own prefix
$(FIG_OUT)/update/%_fixed_summary.dat: input/paper/update/%.nml impact
	@mkdir -p $(dir $@)
	@echo "impact $< (force_update = 'plain')"
	@./impact --set analysis.force_update=plain --set output.prefix=$(FIG_OUT)/update/$*_fixed $< \
	    > $(FIG_OUT)/update/$*_fixed.log 2>&1 || grep -q '^status = diverged' $@ \
	    || { rm -f $@; tail -3 $(FIG_OUT)/update/$*_fixed.log; exit 1; }

$(FIG_OUT)/update/%_bracket_summary.dat: input/paper/update/%.nml impact
	@mkdir -p $(dir $@)
	@echo "impact $< (force_update = 'bracketed')"
	@./impact --set analysis.force_update=bracketed --set output.prefix=$(FIG_OUT)/update/$*_bracket $< \
	    > $(FIG_OUT)/update/$*_bracket.log 2>&1 || { rm -f $@; tail -3 $(FIG_OUT)/update/$*_bracket.log; exit 1; }

figures-clean:
	rm -rf $(FIG_OUT)
