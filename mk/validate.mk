# Validation of the code against exact and published solutions (issue 3).
#
#   make validate    build ./impact and build/validate, run every check of
#                    docs/VALIDATION.md (validation/validate.f90, decks in
#                    validation/decks, results in build/validation), write
#                    docs/VALIDATION.md from validation/VALIDATION.md.in and
#                    draw docs/validation/*.png (validation/plots.gp).
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
	gnuplot validation/plots.gp || status=1; \
	exit $$status
