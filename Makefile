# impact — nonlinear low-velocity impact of composite laminates (Choi, Hong & Lee 1991)
#
#   make            build ./impact
#   make run        install what is missing, build, run input/clamped.nml, plot it
#   make test       install what is missing, build, run the pFUnit tests
#   make check      the tests only, without the set-up (the GNU name)
#   make install    under PREFIX (mk/install.mk)
#   make version    the release number (the file VERSION)
#   make setup      only the Debian packages (tools/setup-debian; make setup-run: the run's only)
#   make fresh-check  the README's two commands in a fresh Debian 12 (tools/fresh-check)
#   make docs       rerun the studies and rewrite the published documents of docs/
#                   (DOCS_DIR below; docs/INSTALL.md, "Regenerating the documents")
#   make clean
#
# Compiler settings can be overridden: make FC=gfortran FFLAGS='-O3 ...'

FC      ?= gfortran
ifeq ($(FC),f77)
FC      := gfortran
endif
BUILD   := build
# The release number is kept in the file VERSION only. The build writes it,
# with the git commit in a checkout, into $(BUILD)/code_version.inc
# (mk/hdf5.mk): `impact --version` and the results' code_version say
# 'impact 1.2.0 (git <commit>[-dirty])', or 'impact 1.2.0' without git.
IMPACT_VERSION := $(shell cat VERSION 2>/dev/null)
ifneq ($(words $(IMPACT_VERSION)),1)
$(error VERSION: one release number expected (as 1.2.0), found '$(IMPACT_VERSION)')
endif
FFLAGS  ?= -O2 -g
# Warnings: -Wall -Wextra, and none is left (CI builds with -Werror, so a new
# one fails it). -Wno-compare-reals: the exact comparisons of reals left in
# the code are meant exactly: a coordinate against the plate's centre line
# (x0 = 0, a value a deck writes exactly), a residual or a stiffness term that
# is exactly zero by arithmetic (a symmetric laminate's B), a number read back
# from its own text; each reads as what it tests.
FSTD    := -std=f2008 -Wall -Wextra -Wno-compare-reals -fimplicit-none -ffpe-summary=none
ifeq ($(CI),true)
FSTD    += -Werror
endif
LAPACK  ?= -llapack -lblas
FC_ALL   = $(FC) $(FSTD) $(FFLAGS) -J$(BUILD) -I$(BUILD)
# Every link line ends with $(LIBS): CHOLMOD, LAPACK and HDF5 (mk/hdf5.mk).
# Recursively expanded, so that no library is looked for while make reads
# this file: make setup, make clean and make -n start on a machine without
# them, and make run installs them before its first compilation.
LIBS     = $(CHOLMOD_LIBS) $(LAPACK) $(HDF5_LIBS)

# CHOLMOD (SuiteSparse; Debian: libsuitesparse-dev) for &analysis storage =
# 'sparse' (and 'auto' on large meshes). src/linalg/cholmod_shim.c is compiled
# against the installed cholmod.h (why C there: its header); the libraries
# go before LAPACK on every link line ($(LIBS)).
CC      ?= cc
CFLAGS  ?= -O2 -g
CSTD    := -std=c99 -Wall -Wextra -pedantic
ifeq ($(CI),true)
CSTD    += -Werror
endif
CHOLMOD_CFLAGS ?= $(shell pkg-config --cflags cholmod 2>/dev/null || echo -I/usr/include/suitesparse)
CHOLMOD_LIBS   ?= -lcholmod -lsuitesparseconfig

# src/ holds the main program and the modules in folders by concern, from
# the bottom of the `use` graph to its top (a folder uses only those before
# it in this list; tools/fortran-deps stops the build otherwise):
#   system    kinds of numbers and their text; the C library, files, limits,
#             signals, the exit status, the build's version
#   linalg    Gauss rules; band, skyline and sparse storage and their
#             factorizations (sparse: CHOLMOD through a C shim, the one C file)
#   deck      the input deck: schema, reader, checks, echo, command line
#   model     the paper's plate and contact: laminate, elements, mesh, scene,
#             indentation law and load, the assembled model
#   strength  ply stresses and failure criteria
#   scheme    the paper's time-step scheme: Newmark, the plate's nonlinear
#             solution, the contact iteration, the one-call 'fast' step
#   results   the result files: history, summary, HDF5, XDMF, the restart file
#   record    the run's record: energies, maxima, warnings, progress, trace,
#             reports, and the restart point that saves it
#   analyses  the static, modal and pressure analyses of the same model
#   accuracy  the accuracy run: a ladder of runs of the program itself (dt
#             halved, the mesh refined), their errors, the run chosen
# Every file but the main program is one module named after the file; the
# objects are flat in $(BUILD); tools/fortran-deps writes the dependencies
# between them from their `use` statements into $(BUILD)/deps.mk.
SRC_FOLDERS := system linalg deck model strength scheme results record analyses accuracy
MAIN    := src/impact.f90
SOURCES := $(foreach d,$(SRC_FOLDERS),$(sort $(wildcard src/$(d)/*.f90)))
OBJS    := $(patsubst %.f90,$(BUILD)/%.o,$(notdir $(SOURCES)))
C_SOURCES := $(foreach d,$(SRC_FOLDERS),$(sort $(wildcard src/$(d)/*.c)))
C_OBJS  := $(patsubst %.c,$(BUILD)/%.o,$(notdir $(C_SOURCES)))
LIB     := $(BUILD)/libimpact.a
vpath %.f90 $(addprefix src/,$(SRC_FOLDERS))
vpath %.c $(addprefix src/,$(SRC_FOLDERS))

# Where the studies (make figures, validate, validate-model, stress, bench)
# write their documents and figures: a mirror of docs/ under out/docs by
# default (out/docs/PAPER.md, out/docs/figures/, out/docs/VALIDATION.md, ...),
# each document filled from a copy of the committed one, so that these
# targets leave the checkout as it was (git status clean, the build's version
# without -dirty). make docs sets DOCS_DIR=docs: the published documents
# themselves (and bench/results.dat, mk/bench.mk).
DOCS_DIR ?= out/docs
# Whether DOCS_DIR is docs/ (however written: docs, docs/, ./docs).
docs_published = $(filter $(CURDIR)/docs,$(abspath $(DOCS_DIR)))

# The validation's oracles (exact and independent solutions: Navier,
# Hertz, the rigid target, ...) are not part of the solver: they live in
# validation/ and are built for make validate and make test only.
ORACLE_SOURCES := validation/reference_solutions.f90 validation/rigid_target.f90 \
                  validation/navier_impact_solution.f90
ORACLE_OBJS    := $(patsubst validation/%.f90,$(BUILD)/oracles/%.o,$(ORACLE_SOURCES))
# The tools' own modules (the HDF5 reader of tools/h5export and the tests).
TOOL_OBJS      := $(BUILD)/tools/hdf5_read.o

.PHONY: all run test setup setup-run clean reference
all: impact

$(BUILD):
	@mkdir -p $(BUILD)

$(OBJS): $(BUILD)/%.o: %.f90 | $(BUILD)
	$(FC_ALL) -c $< -o $@

$(C_OBJS): $(BUILD)/%.o: %.c | $(BUILD)
	$(CC) $(CSTD) $(CFLAGS) $(CHOLMOD_CFLAGS) -c $< -o $@

# The element work of a time step is written for the vectoriser, which GCC
# applies at -O2 only to loops whose trip count it knows: let it weigh the
# others too (docs/PERFORMANCE.md, "The element work of a step").
$(BUILD)/element_work.o: private FC_ALL += -fvect-cost-model=dynamic

$(BUILD)/deps.mk: $(SOURCES) tools/fortran-deps | $(BUILD)
	@python3 tools/fortran-deps $(BUILD) '$(SRC_FOLDERS)' $(SOURCES) > $@.tmp && mv $@.tmp $@
# Read (and so written) only where a goal compiles: the set-up targets, run
# and test (which set up first, then build in a second make), clean and
# version start without python3; so does make -n.
SETUP_GOALS := run test setup setup-run clean version fresh-check hdf5-config uninstall
ifneq ($(filter-out $(SETUP_GOALS),$(or $(MAKECMDGOALS),all)),)
ifeq ($(findstring n,$(firstword -$(MAKEFLAGS))),)
-include $(BUILD)/deps.mk
endif
endif

# What a compilation needs that make cannot make: python3 (tools/fortran-deps
# wrote $(BUILD)/deps.mk) and HDF5-Fortran (mk/hdf5.mk); a missing one stops
# the build here with what to do, before the first compiler's message.
.PHONY: build-needs
build-needs:
	@test -f $(BUILD)/deps.mk || { echo 'make: python3 not found (tools/fortran-deps orders the build): make setup' >&2; exit 1; }
	$(hdf5_check)
$(OBJS) $(C_OBJS): | build-needs

$(LIB): $(OBJS) $(C_OBJS)
	ar rcs $@ $^

$(BUILD)/tools/%.o: tools/%.f90 $(LIB)
	@mkdir -p $(BUILD)/tools
	$(FC_ALL) -c $< -o $@

$(BUILD)/oracles/%.o: validation/%.f90 $(LIB)
	@mkdir -p $(BUILD)/oracles
	$(FC_ALL) -c $< -o $@
# (in the order of their use statements)
$(BUILD)/oracles/rigid_target.o: $(BUILD)/oracles/reference_solutions.o
$(BUILD)/oracles/navier_impact_solution.o: $(BUILD)/oracles/reference_solutions.o

# The main program is built without gfortran's run-time backtrace, so that a
# bad deck ends with its one-line message (error stop 1) and not a stack dump;
# rebuild with MAIN_FLAGS= to get backtraces back when debugging a crash.
MAIN_FLAGS ?= -fno-backtrace
impact: $(MAIN) $(LIB)
	$(FC_ALL) $(MAIN_FLAGS) $(MAIN) $(LIB) $(LIBS) -o $@

setup:
	@sh tools/setup-debian

# only what the run needs (no ParaView, no test tools)
setup-run:
	@sh tools/setup-debian run

# The README's two commands in a fresh Debian 12 tree (tools/fresh-check:
# what it needs, about 15 minutes); before each release.
.PHONY: fresh-check
fresh-check:
	@sh tools/fresh-check $(FRESH_DIR)

# Set up first, then build in a second make that reads the Makefile anew.
run: setup-run
	@$(MAKE) --no-print-directory impact
	@mkdir -p out
	./impact < input/clamped.nml
	gnuplot -e "prefix='out/clamped'" postproc/history.gp
	@echo "plot written: out/clamped_history.png"

# After an intended change of results: rewrite the stored reference of the
# regression test (tests/test_regression.pf) and say why in the commit.
reference: impact
	./impact tests/data/regression/clamped.nml > /dev/null
	cp build/tests/regression/clamped_history.dat tests/data/regression/clamped_history.dat

clean:
	rm -rf $(BUILD) impact

# check: the GNU name of the tests, the tests only (make test without its
# set-up: no apt-get; make setup installs); version: the release number.
.PHONY: check version
check: test-funit test-build
	$(TEST_EXE)
version:
	@echo '$(IMPACT_VERSION)'

include tests/tests.mk
# Further targets (figures, validation, benchmarks, ...) live in mk/*.mk.
-include $(sort $(wildcard mk/*.mk))

# The deck table of docs/DECK.md, from the schema of src/deck/deck_schema.f90 (between
# the markers <!-- deck:begin --> and <!-- deck:end -->).
.PHONY: deck-table
deck-table: impact
	@python3 tools/readme-deck-table docs/DECK.md ./impact

# ---- the published documents (docs/INSTALL.md, "Regenerating the documents")
#
#   make docs         rerun every study with DOCS_DIR=docs: docs/PAPER.md and
#                     docs/figures/ (figures), docs/VALIDATION.md and
#                     docs/validation/ (validate, validate-model),
#                     docs/STABILITY.md (stress), docs/PERFORMANCE.md,
#                     docs/performance/ and bench/results.dat (the full bench
#                     grid), the table of docs/DECK.md (deck-table). About 40
#                     minutes on 2 cores; one study at a time (the bench times
#                     its runs); a study that fails a check still writes its
#                     document, and make docs goes on, then exits 1. The
#                     bench refuses BENCH_ARGS=--quick here (bench/run_bench.py).
#                     Review the diff, then commit it.
#   make docs-quick   the same studies with the small bench grid
#                     (BENCH_ARGS=--quick), into DOCS_DIR (out/docs): a
#                     preview; it refuses DOCS_DIR=docs.
DOCS_STUDIES := deck-table validate validate-model stress figures bench

.PHONY: docs docs-quick
docs:
	@status=0; for t in $(DOCS_STUDIES); do \
	    $(MAKE) --no-print-directory $$t DOCS_DIR=docs || { status=1; failed="$$failed $$t"; }; \
	done; \
	echo "make docs: wrote docs/ and bench/results.dat$${failed:+ (failed:$$failed)}; review git diff, then commit"; \
	exit $$status

docs-quick:
	$(if $(docs_published),$(error make docs-quick: DOCS_DIR=$(DOCS_DIR): the quick studies never write docs/ (make docs does)))
	@status=0; for t in $(filter-out deck-table,$(DOCS_STUDIES)); do \
	    $(MAKE) --no-print-directory $$t DOCS_DIR='$(DOCS_DIR)' BENCH_ARGS=--quick || { status=1; failed="$$failed $$t"; }; \
	done; \
	echo "make docs-quick: wrote $(DOCS_DIR)/ and out/bench/results.dat$${failed:+ (failed:$$failed)}"; \
	exit $$status
