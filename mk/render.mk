# Pictures of one run (README, "Pictures of a run"):
#
#   make plots  [PREFIX_RUN=out/clamped]
#                 gnuplot: PREFIX_RUN_history.png (force, displacements, strain,
#                 energies; postproc/history.gp), PREFIX_RUN_contact_loop.png
#                 (force against indentation; postproc/contact_loop.gp) and, for a
#                 run with &strength, PREFIX_RUN_damage.png (the damage map ply
#                 by ply; postproc/damage_map.gp, over tools/damage-map and h5py)
#   make render [PREFIX_RUN=out/clamped] [RENDER_SIZE=1600x900]
#                 ParaView from PREFIX_RUN.xdmf (postproc/render.py under
#                 xvfb-run: Debian's ParaView 5.11 aborts on a render without a
#                 display, offscreen too): PREFIX_RUN_render_w.png, w at the
#                 peak force, and with &strength PREFIX_RUN_render_damage.png
#   make pictures [PREFIX_RUN=...]   both
#   make pictures-example
#                 runs input/paper/strength/fig10_clamped_nonlinear.nml (the
#                 paper's clamped plate with &strength, about 3 s) and draws
#                 its pictures in out/paper/strength/
#
# PREFIX_RUN is a run's &output prefix (make run writes out/clamped). The
# picture tools are those of make setup (gnuplot, xvfb, python3-paraview,
# python3-h5py); PVPYTHON (pvpython, or Debian's /usr/bin/python3) runs
# render.py.

PREFIX_RUN  ?= out/clamped
RENDER_SIZE ?= 1600x900
PVPYTHON    ?= pvpython
# The X server without a screen. -noreset: an X server resets when its last
# client leaves, and ParaView opens and closes a connection before it makes
# its view; a view made during the reset found no server ("bad X server
# connection", an abort) in 3 renders of 8 on a loaded machine, none of 10
# without the reset.
XVFB_RUN    := xvfb-run -a -s '-screen 0 1280x1024x24 -noreset'
RENDER_DECK := input/paper/strength/fig10_clamped_nonlinear.nml
RENDER_EXAMPLE := out/paper/strength/fig10_clamped_nonlinear

.PHONY: plots render pictures pictures-example

# a run's file must be there before anything is drawn
render_need = @test -f '$(1)' || { echo 'make $@: $(1) not found: run a deck with prefix = '\''$(PREFIX_RUN)'\'' first (make run writes out/clamped)' >&2; exit 1; }

plots:
	$(call render_need,$(PREFIX_RUN)_history.dat)
	gnuplot -e "prefix='$(PREFIX_RUN)'" postproc/history.gp
	gnuplot -e "prefix='$(PREFIX_RUN)'" postproc/contact_loop.gp
	@if grep -q '^max_failure_index' '$(PREFIX_RUN)_summary.dat' 2>/dev/null; then \
	    echo "gnuplot -e \"prefix='$(PREFIX_RUN)'\" postproc/damage_map.gp"; \
	    gnuplot -e "prefix='$(PREFIX_RUN)'" postproc/damage_map.gp || exit 1; \
	fi
	@echo 'plots written: $(PREFIX_RUN)_history.png, $(PREFIX_RUN)_contact_loop.png (and _damage.png with &strength)'

render:
	$(call render_need,$(PREFIX_RUN).xdmf)
	@command -v xvfb-run > /dev/null || { echo 'make render: xvfb-run not found (Debian: apt-get install xvfb xauth; make setup)' >&2; exit 1; }
	$(XVFB_RUN) $(PVPYTHON) postproc/render.py '$(PREFIX_RUN)' --size $(RENDER_SIZE)

pictures: plots render

pictures-example: impact
	./impact $(RENDER_DECK) > /dev/null
	@$(MAKE) --no-print-directory pictures PREFIX_RUN=$(RENDER_EXAMPLE)
