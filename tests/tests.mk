# The pFUnit tests, tests/test_*.pf (included at the end of the top Makefile).
#
#   make test              install what is missing (setup), check the test
#                          framework (test-funit), build $(LIB), ./impact and
#                          the tests, run every test from the repository root
#   make test-funit        only the framework's self-check
#   make test PFUNIT_DIR=<pFUnit install>
#                          build and run the same .pf files with real pFUnit
#                          (4.13 or later: older ones exit 0 on failures)
#   build/tests/run_tests WORD...
#                          rerun only the tests whose module.name contains WORD
#
# Without PFUNIT_DIR, tests/funit/pf2f90.py translates each .pf file into
# build/tests/<name>.F90, running on tests/funit/funit.f90 (a stand-in for
# pFUnit's funit module), and writes the driver build/tests/funit_driver.f90,
# which prints PASS or FAIL per test and "N passed, N failed" last.  The .pf
# files may use only the pFUnit subset pf2f90.py accepts (see its header), so
# that they also build with pFUnit.

PYTHON     ?= python3
FUNIT      := tests/funit
TEST_BUILD := $(BUILD)/tests
TEST_PF    := $(sort $(wildcard tests/test_*.pf))

.PHONY: test test-funit test-build FORCE

test: setup
	@$(MAKE) --no-print-directory test-funit
	@$(MAKE) --no-print-directory test-build
	$(TEST_EXE)

$(TEST_BUILD):
	@mkdir -p $@

$(TEST_BUILD)/funit.o: $(FUNIT)/funit.f90 | $(TEST_BUILD)
	$(FC_ALL) -c $< -o $@

# What the tests share (tests/test_helpers.f90), linked with them in both routes.
HELPER_OBJS := $(TEST_BUILD)/test_helpers.o
$(HELPER_OBJS): tests/test_helpers.f90 $(LIB) | $(TEST_BUILD)
	$(FC_ALL) -c $< -o $@

# The translator refuses what is outside the subset (tests/funit/reject/*.pf),
# and a small suite with deliberate failures, built in a temporary directory,
# makes the driver report them and fail (tests/funit/selfcheck/).
test-funit: $(TEST_BUILD)/funit.o
	@sh $(FUNIT)/selfcheck.sh '$(PYTHON)' '$(FC)' '$(FSTD) $(FFLAGS)' '$(BUILD)' '$<'

# The regression tests run the program itself (./impact).
test-build: impact

ifdef PFUNIT_DIR
# ---- real pFUnit 4: its PFUNIT.mk and make_pfunit_test, in build/pfunit ----
TEST_EXE := $(BUILD)/pfunit/impact_tests

# pf2f90.py checks that the tests stay in the subset the default route builds;
# pfunit.mk stops on a pFUnit older than 4.13, before anything is built.
test-build: pfunit-check
test-build: $(LIB) $(ORACLE_OBJS) $(TOOL_OBJS) $(HELPER_OBJS)
	@mkdir -p $(BUILD)/pfunit
	$(PYTHON) $(FUNIT)/pf2f90.py --driver $(BUILD)/pfunit/subset_check.f90 $(TEST_PF)
	$(MAKE) -C $(BUILD)/pfunit -f $(CURDIR)/$(FUNIT)/pfunit.mk impact_tests \
	    PFUNIT_DIR='$(abspath $(PFUNIT_DIR))' FC='$(FC)' FFLAGS='$(FFLAGS)' \
	    IMPACT_TESTS='$(abspath $(TEST_PF))' IMPACT_LIB='$(abspath $(ORACLE_OBJS) $(TOOL_OBJS) $(HELPER_OBJS) $(LIB))' \
	    IMPACT_MODULES='$(abspath $(BUILD))' LAPACK='$(LIBS)'

.PHONY: pfunit-check
pfunit-check:
	@$(MAKE) --no-print-directory -f $(FUNIT)/pfunit.mk pfunit-version PFUNIT_DIR='$(abspath $(PFUNIT_DIR))'

else
# ---- default: translate with pf2f90.py, build with $(FC_ALL) ----
TEST_SRC := $(patsubst tests/%.pf,$(TEST_BUILD)/%.F90,$(TEST_PF))
TEST_OBJ := $(TEST_SRC:.F90=.o)
TEST_EXE := $(TEST_BUILD)/run_tests

test-build: $(TEST_EXE)

# Keep the translations: compiler and run-time messages point into them
# (through #line, at the .pf lines).
.SECONDARY: $(TEST_SRC)

$(TEST_BUILD)/%.F90: tests/%.pf $(FUNIT)/pf2f90.py | $(TEST_BUILD)
	$(PYTHON) $(FUNIT)/pf2f90.py $< -o $@

# The driver lists every test: rewrite it when a .pf file changes, comes or goes
# (test-list changes only when the set of files does).
$(TEST_BUILD)/test-list: FORCE | $(TEST_BUILD)
	@echo '$(TEST_PF)' | cmp -s - $@ || echo '$(TEST_PF)' > $@

$(TEST_BUILD)/funit_driver.f90: $(TEST_BUILD)/test-list $(TEST_PF) $(FUNIT)/pf2f90.py
	$(PYTHON) $(FUNIT)/pf2f90.py --driver $@ $(TEST_PF)

$(TEST_BUILD)/%.o: $(TEST_BUILD)/%.F90 $(TEST_BUILD)/funit.o $(ORACLE_OBJS) $(TOOL_OBJS) $(HELPER_OBJS) $(LIB)
	$(FC_ALL) -c $< -o $@

$(TEST_EXE): $(TEST_BUILD)/funit_driver.f90 $(TEST_OBJ) $(TEST_BUILD)/funit.o $(ORACLE_OBJS) $(TOOL_OBJS) $(HELPER_OBJS) $(LIB)
	$(FC_ALL) $< $(TEST_OBJ) $(TEST_BUILD)/funit.o $(ORACLE_OBJS) $(TOOL_OBJS) $(HELPER_OBJS) $(LIB) $(LIBS) -o $@
endif
