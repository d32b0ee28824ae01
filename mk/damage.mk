# The ply damage study (docs/validation/damage.md).
#
#   make validate-damage   build ./impact, run validation/damage/run.py: the
#                          paper's clamped plate with ply damage at 1, 3, 6
#                          and 10 J against the elastic plate, and the
#                          energy dissipated on four meshes with and without
#                          the crack band (decks, outputs and the tables,
#                          tables.md, in build/validation/damage). About
#                          2 minutes of CPU. Exit 1 when a run fails.

.PHONY: validate-damage

validate-damage: setup impact
	@mkdir -p build/validation/damage
	$(or $(PYTHON),python3) validation/damage/run.py
