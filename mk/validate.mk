# Validation of the code against exact and published solutions (issue 3).
#
#   make validate    build ./impact and build/validate, run every check of
#                    docs/VALIDATION.md (validation/validate.f90, decks in
#                    validation/decks, results in build/validation), write
#                    docs/VALIDATION.md from validation/VALIDATION.md.in (its
#                    blocks filled with the tables build/validation/NAME.md by
#                    tools/impact_files.py fill) and draw docs/validation/*.png
#                    (validation/plots.gp).
#                    Fails (exit 1) when a check is outside its tolerance;
#                    the report and the plots are written either way.
#                    About 3 minutes of one core.

VALIDATE_EXE := $(BUILD)/validate

.PHONY: validate

$(VALIDATE_EXE): validation/validate.f90 $(ORACLE_OBJS) $(LIB)
	$(FC_ALL) $< $(ORACLE_OBJS) $(LIB) $(LAPACK) -o $@

validate: setup impact $(VALIDATE_EXE)
	@mkdir -p build/validation docs/validation
	@status=0; $(VALIDATE_EXE) || status=$$?; \
	$(or $(PYTHON),python3) tools/impact_files.py fill docs/VALIDATION.md build/validation || status=1; \
	gnuplot validation/plots.gp || status=1; \
	exit $$status

# The Navier modal impact solution of the simply supported plate, the
# reference for ./impact's dynamic point response (validation/navier_impact.f90,
# module validation/navier_impact_solution.f90; tests/test_navier_impact.pf).
#
#   make navier-impact      build build/navier_impact
#   build/navier_impact deck.nml [--load hertz|point] [--mmax N] [--max-mmax N] [--tol X] [--out prefix]
#
# The module is one of the oracles (Makefile, ORACLE_OBJS), linked with the tests too.
NAVIER_IMPACT := $(BUILD)/navier_impact

.PHONY: navier-impact
navier-impact: $(NAVIER_IMPACT)

# (without the run-time backtrace, as ./impact: bad input ends with one line)
$(NAVIER_IMPACT): validation/navier_impact.f90 $(ORACLE_OBJS) $(LIB)
	$(FC_ALL) $(MAIN_FLAGS) $< $(ORACLE_OBJS) $(LIB) $(LAPACK) -o $@
