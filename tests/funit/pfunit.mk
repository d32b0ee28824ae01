# Builds tests/test_*.pf against real pFUnit 4, as its documentation says:
# include PFUNIT.mk, add $(PFUNIT_EXTRA_FFLAGS) to FFLAGS, describe the suite
# with <name>_TESTS and <name>_OTHER_LIBRARIES, then
# $(eval $(call make_pfunit_test,<name>)).
#
# Requires pFUnit 4.13 or later (below). Run by tests/tests.mk (make test
# PFUNIT_DIR=...) inside build/pfunit, where
# pFUnit's rules leave their files (the generated .F90, the .inc suite list,
# objects and modules); it passes
#   PFUNIT_DIR      the pFUnit install: the directory holding include/PFUNIT.mk,
#                   or the prefix holding PFUNIT-<version>/include/PFUNIT.mk
#   FC, FFLAGS      the compiler and the project's flags
#   IMPACT_TESTS    the .pf files (absolute paths)
#   IMPACT_LIB      build/libimpact.a (after the objects of the validation
#                   oracles the tests use), IMPACT_MODULES their .mod directory
#   LAPACK          the LAPACK and BLAS link flags

PFUNIT_MK := $(firstword $(wildcard $(PFUNIT_DIR)/include/PFUNIT.mk \
                                    $(PFUNIT_DIR)/PFUNIT-*/include/PFUNIT.mk))
ifeq ($(PFUNIT_MK),)
$(error no PFUNIT.mk in $(PFUNIT_DIR)/include or $(PFUNIT_DIR)/PFUNIT-*/include: \
  set PFUNIT_DIR to a pFUnit 4 installation)
endif
include $(PFUNIT_MK)

# pFUnit 4.12 and older exit with status 0 when tests fail, so that make test
# would pass with failing tests: require 4.13 or later. PFUNIT.mk sets
# PFUNIT_VERSION (major.minor); failing that, the install directory
# PFUNIT-<major>.<minor> tells. `make -f pfunit.mk pfunit-version` only checks.
PFUNIT_MIN_MAJOR := 4
PFUNIT_MIN_MINOR := 13
pfunit_version := $(strip $(or $(PFUNIT_VERSION),\
    $(patsubst PFUNIT-%,%,$(lastword $(filter PFUNIT-%,$(subst /, ,$(PFUNIT_MK)))))))
pfunit_major := $(word 1,$(subst ., ,$(pfunit_version)))
pfunit_minor := $(word 2,$(subst ., ,$(pfunit_version)))
pfunit_recent := $(shell { [ '$(pfunit_major)' -gt $(PFUNIT_MIN_MAJOR) ] || \
    { [ '$(pfunit_major)' -eq $(PFUNIT_MIN_MAJOR) ] && [ '$(pfunit_minor)' -ge $(PFUNIT_MIN_MINOR) ]; }; } \
    2>/dev/null && echo yes)
ifneq ($(pfunit_recent),yes)
$(error pFUnit $(or $(pfunit_version),of unknown version) at $(PFUNIT_MK): impact's tests need pFUnit \
  $(PFUNIT_MIN_MAJOR).$(PFUNIT_MIN_MINOR) or later (4.12 and older exit with status 0 when tests fail); \
  install a newer pFUnit, or run make test without PFUNIT_DIR)
endif

.PHONY: pfunit-version
pfunit-version:
	@echo 'pFUnit $(pfunit_version): $(PFUNIT_MK)'

# The suite list pFUnit writes (impact_tests.inc) names each suite after its
# file (test_x.pf -> test_x_suite) and its preprocessor names it after the
# module, hence pf2f90.py's rule: module test_x lives in test_x.pf.
vpath %.pf $(sort $(dir $(IMPACT_TESTS)))

override FFLAGS += $(PFUNIT_EXTRA_FFLAGS) -I$(IMPACT_MODULES)
ifneq ($(findstring gfortran,$(FC)),)
override FFLAGS += -ffree-line-length-none
endif

%.o: %.F90
	$(FC) -c $(FFLAGS) $< -o $@

impact_tests_TESTS := $(notdir $(IMPACT_TESTS))
impact_tests_OTHER_LIBRARIES := $(IMPACT_LIB) $(LAPACK)
$(eval $(call make_pfunit_test,impact_tests))

# Rebuild when the library (and so its modules) changes.
$(patsubst %.pf,%.o,$(impact_tests_TESTS)) impact_tests: $(IMPACT_LIB)
