# The example sweep of the docs/SWEEPS.md: 48 scenes of
# the paper's plate (tools/sweep), run on all the CPUs this process may use
# (SWEEP_JOBS=N: N at a time), then the table and the plot of peak force
# against impact energy.
#
#   make sweep-example [SWEEP_DIR=out/sweep48] [SWEEP_JOBS=N]
#
# 3 masses x 4 velocities x 2 edge conditions x 2 meshes; input/clamped.nml
# is the template. Rerunning it runs only the scenes that have not completed.
SWEEP_DIR  ?= out/sweep48
SWEEP_JOBS ?= 0

.PHONY: sweep-example
sweep-example: impact
	tools/sweep init $(SWEEP_DIR) --deck input/clamped.nml \
	    --vary impactor.mass=0.1,0.243,0.5 --vary impactor.velocity=1,2,3,4 \
	    --vary boundary.edges=clamped,simply_supported --vary mesh.nx+mesh.ny=6:4,9:6
	tools/sweep run $(SWEEP_DIR) $(if $(filter-out 0,$(SWEEP_JOBS)),--jobs $(SWEEP_JOBS)) \
	    || echo 'make sweep-example: some scenes failed: see $(SWEEP_DIR)/failed.dat'
	tools/sweep plot $(SWEEP_DIR) --x initial_energy_J --y peak_force_N --by boundary.edges
	@echo 'make sweep-example: wrote $(SWEEP_DIR)/ (table.dat and the plot)'
