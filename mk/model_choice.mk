# Model choices: Whitney's shear correction factors, the domain
# 'auto' picks, the symmetry check, the scene report's estimate against
# runs, graded against uniform meshes.
#
#   make validate-model   build ./impact, run validation/model_choice/run.py
#                         (decks and outputs in build/validation/model_choice),
#                         write $(DOCS_DIR)/validation/model_choice.md and
#                         $(DOCS_DIR)/validation/model_choice/grading.{dat,png}
#                         (DOCS_DIR, the top Makefile: out/docs by default,
#                         docs under make docs).
#                         Fails (exit 1) when a check is outside its
#                         tolerance; the report is written either way.
#                         The runs go through impact_files.run_many on all
#                         the CPUs this process may use (about 3 minutes of
#                         CPU; 2 of wall time on 2 cores).

PYTHON ?= python3

.PHONY: validate-model

validate-model: setup impact
	@mkdir -p build/validation/model_choice '$(DOCS_DIR)/validation/model_choice'
	$(PYTHON) validation/model_choice/run.py --docs-dir '$(DOCS_DIR)'
