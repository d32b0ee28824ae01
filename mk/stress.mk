# make stress: ./impact far from the paper's scene (issue 6).
#
#   make stress     build ./impact, run every scene of tools/stress/stress.py
#                   (two at a time), check each (no NaN or Inf, converged or
#                   stopped with a diagnostic, energy within the stated bound)
#                   and write build/stress/results.dat and the generated
#                   blocks of docs/STABILITY.md (in place). Exit status 1 when a
#                   scene fails a check. About 3 to 4 minutes on 2 shared cores.
#   make stress STRESS_JOBS=1   one scene at a time

STRESS_JOBS ?= 2

.PHONY: stress
stress: setup impact
	$(or $(PYTHON),python3) tools/stress/stress.py --jobs $(STRESS_JOBS)
