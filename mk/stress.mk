# make stress: ./impact far from the paper's scene.
#
#   make stress     build ./impact, run every scene of tools/stress/stress.py
#                   (two at a time), check each (no NaN or Inf, converged or
#                   stopped with a diagnostic, energy within the stated bound)
#                   and write build/stress/results.dat and
#                   $(DOCS_DIR)/STABILITY.md, docs/STABILITY.md with its
#                   generated blocks filled (DOCS_DIR, the top Makefile:
#                   out/docs by default; docs under make docs, in place).
#                   Exit status 1 when a scene fails a check. About 30 s on
#                   2 idle cores, 3 to 4 minutes on 2 shared ones.
#   make stress STRESS_JOBS=1   one scene at a time
#   make stress STRESS_ONLY='paper m_1g'
#                   only these scenes; their report is not the published
#                   one: refused with DOCS_DIR=docs
#   make stress STRESS_RANDOM=160 [STRESS_SEED=2]
#                   instead 160 random extreme scenes (scheme 'fast', 400
#                   steps each; tools/stress/stress.py random_scenes), the
#                   same for the same seed; refused with DOCS_DIR=docs

STRESS_JOBS ?= 2
STRESS_ONLY ?=
STRESS_RANDOM ?=
STRESS_SEED ?= 1

.PHONY: stress
stress: setup impact
	$(or $(PYTHON),python3) tools/stress/stress.py --jobs $(STRESS_JOBS) --docs-dir '$(DOCS_DIR)' \
	    $(if $(strip $(STRESS_ONLY)),--only $(STRESS_ONLY)) \
	    $(if $(strip $(STRESS_RANDOM)),--random $(STRESS_RANDOM) --seed $(STRESS_SEED))
