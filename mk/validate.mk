# Validation of the code against exact and published solutions.
#
#   make validate    build ./impact and build/validate, run every check of
#                    docs/VALIDATION.md (validation/validate.f90, decks in
#                    validation/decks, results and tables in build/validation),
#                    write $(DOCS_DIR)/VALIDATION.md: build/validate copies
#                    the template validation/VALIDATION.md.in there, then
#                    tools/impact_files.py fill fills its blocks with the
#                    tables build/validation/NAME.md; and draw
#                    $(DOCS_DIR)/validation/*.png (validation/plots.gp).
#                    DOCS_DIR (the top Makefile) is out/docs by default, docs
#                    under make docs (the published docs/VALIDATION.md).
#                    Fails (exit 1) when a check is outside its tolerance;
#                    the report and the plots are written either way.
#                    About 3 minutes of one core, and check 12 (below).
#   make validate-accuracy
#                    check 12 alone: the error bars of impact --accuracy
#                    against the true errors on ten scenes
#                    (validation/accuracy_validation.f90, decks in
#                    validation/decks/accuracy, results in
#                    build/validation/accuracy); its tables go into
#                    docs/VALIDATION.md at the next make validate. Runs its
#                    references on every CPU the process may use; tens of
#                    minutes of cpu.

VALIDATE_EXE := $(BUILD)/validate
NAVIER_IMPACT := $(BUILD)/navier_impact
ACCURACY_VALIDATION := $(BUILD)/accuracy_validation

.PHONY: validate validate-accuracy

$(VALIDATE_EXE): validation/validate.f90 $(ORACLE_OBJS) $(LIB)
	$(FC_ALL) $< $(ORACLE_OBJS) $(LIB) $(LIBS) -o $@

$(ACCURACY_VALIDATION): validation/accuracy_validation.f90 $(LIB)
	$(FC_ALL) $< $(LIB) $(LIBS) -o $@

# check 12 first: the report that validate assembles includes its tables
validate: setup impact $(VALIDATE_EXE) $(ACCURACY_VALIDATION) $(NAVIER_IMPACT)
	@mkdir -p build/validation '$(DOCS_DIR)/validation'
	@status=0; $(ACCURACY_VALIDATION) || status=$$?; \
	$(VALIDATE_EXE) '$(DOCS_DIR)/VALIDATION.md' || status=$$?; \
	$(or $(PYTHON),python3) tools/impact_files.py fill '$(DOCS_DIR)/VALIDATION.md' build/validation || status=1; \
	gnuplot -e "figdir='$(DOCS_DIR)/validation'" validation/plots.gp || status=1; \
	gnuplot -e "figdir='$(DOCS_DIR)/validation'" validation/accuracy_plots.gp || status=1; \
	echo 'make validate: wrote $(DOCS_DIR)/VALIDATION.md and $(DOCS_DIR)/validation/*.png (tables in build/validation/)'; \
	exit $$status

validate-accuracy: impact $(ACCURACY_VALIDATION) $(NAVIER_IMPACT)
	@mkdir -p build/validation '$(DOCS_DIR)/validation'
	$(ACCURACY_VALIDATION)
	gnuplot -e "figdir='$(DOCS_DIR)/validation'" validation/accuracy_plots.gp

# The Navier modal impact solution of the simply supported plate, the
# reference for ./impact's dynamic point response (validation/navier_impact.f90,
# module validation/navier_impact_solution.f90; tests/test_navier_impact.pf).
#
#   make navier-impact      build build/navier_impact
#   build/navier_impact deck.nml [--load hertz|point] [--mmax N] [--max-mmax N] [--tol X] [--out prefix]
#
# The module is one of the oracles (Makefile, ORACLE_OBJS), linked with the tests too.
# (NAVIER_IMPACT is set at the top: the prerequisites above read it as they are parsed.)

.PHONY: navier-impact
navier-impact: $(NAVIER_IMPACT)

# (without the run-time backtrace, as ./impact: bad input ends with one line)
$(NAVIER_IMPACT): validation/navier_impact.f90 $(ORACLE_OBJS) $(LIB)
	$(FC_ALL) $(MAIN_FLAGS) $< $(ORACLE_OBJS) $(LIB) $(LIBS) -o $@
