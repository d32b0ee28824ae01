# HDF5-Fortran for the results file <prefix>.h5 (src/results/hdf5_io.f90,
# src/results/results_hdf5.f90), the exporter build/h5export and the shape picture.
#
#   make shape [SHAPE_PREFIX=out/clamped]
#                     the deflected shape at the peak force: build/h5export
#                     turns SHAPE_PREFIX.h5 into SHAPE_PREFIX_shape.dat, and
#                     postproc/shape.gp draws SHAPE_PREFIX_shape.png; runs
#                     ./impact on input/clamped.nml first when the default
#                     out/clamped.h5 is missing
#   make h5export     only the exporter (tools/h5export.f90)
#   make hdf5-config  where HDF5 was found, and the flags
#
# HDF5 is looked for, in this order:
#   1. HDF5_ROOT (set by cluster modules): $(HDF5_ROOT)/bin/h5fc when there is
#      one, else $(HDF5_ROOT)/include and $(HDF5_ROOT)/lib;
#   2. h5fc on PATH (Debian: libhdf5-dev; another name: H5FC=...);
#   3. pkg-config: hdf5-fortran, else hdf5 with the Fortran libraries beside it.
# or given outright:  make HDF5_FFLAGS='-I<dir of hdf5.mod>' HDF5_LIBS='-L<dir> -lhdf5_fortran -lhdf5 ...'
# The compile flags are appended to FFLAGS, the libraries end $(LIBS) (the top
# Makefile's link line is  $(FC_ALL) $(MAIN) $(LIB) $(LIBS)).
#
# The search runs when a recipe first needs the flags, not when make reads
# this file: `make run` and `make test` install libhdf5-dev (tools/setup-debian)
# before they compile anything, on a fresh machine too. When nothing is found,
# the build stops before its first compilation and says what to do.

comma := ,
# The HDF5 Fortran compiler wrapper looked for on PATH (H5FC=none skips it).
# Its static libraries when it has them (h5fc -noshlib: every archive it
# names exists), else its shared ones. Linked statically, HDF5 brings in
# only what the code calls: the program starts without the 30-odd shared
# libraries that Debian's libhdf5.so needs for its S3 driver (libcurl,
# libcrypto and theirs), 8 ms instead of 23 ms of cpu for impact --version
# (docs/PERFORMANCE.md), which a sweep of short scenes or an accuracy
# ladder pays once per run; the shared libraries it names and the code
# does not need are dropped (--as-needed, HDF5_LIBS below).
H5FC ?= h5fc
hdf5_h5fc_static = $(wordlist 2,1000,$(shell '$(1)' -noshlib -show 2>/dev/null))
hdf5_h5fc_shared = $(wordlist 2,1000,$(shell '$(1)' -shlib -show 2>/dev/null || '$(1)' -show 2>/dev/null))
# the words when they name archives and every one exists, else nothing
hdf5_if_archives = $(if $(filter %.a,$(1)),$(if $(filter-out $(wildcard $(filter %.a,$(1))),$(filter %.a,$(1))),,$(1)))
hdf5_h5fc_words = $(or $(call hdf5_if_archives,$(call hdf5_h5fc_static,$(1))),$(call hdf5_h5fc_shared,$(1)))
hdf5_root_words = -I$(HDF5_ROOT)/include -L$(HDF5_ROOT)/lib -lhdf5hl_fortran -lhdf5_hl -lhdf5_fortran -lhdf5
hdf5_pkg_words = $(shell pkg-config --cflags --libs hdf5-fortran 2>/dev/null || \
    pkg-config --cflags --libs hdf5_fortran 2>/dev/null || \
    { pkg-config --exists hdf5 2>/dev/null && echo $$(pkg-config --cflags hdf5) \
          -lhdf5hl_fortran -lhdf5_hl -lhdf5_fortran $$(pkg-config --libs hdf5); })

# Where HDF5 comes from, and the words of its compile and link line.
hdf5_find = $(strip \
    $(if $(HDF5_ROOT),\
        $(if $(wildcard $(HDF5_ROOT)/bin/h5fc),\
            h5fc:$(HDF5_ROOT)/bin/h5fc $(call hdf5_h5fc_words,$(HDF5_ROOT)/bin/h5fc),\
            HDF5_ROOT:$(HDF5_ROOT) $(hdf5_root_words)),\
        $(if $(shell command -v '$(H5FC)' 2>/dev/null),\
            h5fc:$(shell command -v '$(H5FC)') $(call hdf5_h5fc_words,$(H5FC)),\
            $(if $(hdf5_pkg_words),pkg-config $(hdf5_pkg_words),none))))
# Memoised: searched once per make, on first use.
hdf5_found = $(eval hdf5_found := $$(hdf5_find))$(hdf5_found)

# Not found: no flags, and build-needs (top Makefile) stops the build.
hdf5_none = $(filter none,$(firstword $(hdf5_found)))
hdf5_words = $(if $(hdf5_none),,$(wordlist 2,1000,$(hdf5_found)))
hdf5_check_found = $(if $(hdf5_none),\
    @echo 'make: HDF5-Fortran not found (no HDF5_ROOT, no h5fc on PATH, no pkg-config hdf5).' \
    'On Debian: make setup (installs libhdf5-dev); on a cluster: module load hdf5 (sets HDF5_ROOT)' \
    'or make HDF5_ROOT=<install prefix>; or give HDF5_FFLAGS and HDF5_LIBS' >&2; exit 1)

ifeq ($(origin HDF5_FFLAGS),undefined)
HDF5_FFLAGS = $(filter -I%,$(hdf5_words))
endif
ifeq ($(origin HDF5_LIBS),undefined)
hdf5_check = $(hdf5_check_found)
# The libraries and their directories, each also as a run-time path (cluster
# installs are outside the loader's default path); archives before the
# libraries they call, and of these only the ones called are kept.
HDF5_LIBS = -Wl,--as-needed $(filter -L%,$(hdf5_words)) $(filter %.a %.so,$(hdf5_words)) \
    $(filter -l% -Wl%,$(hdf5_words)) $(patsubst -L%,-Wl$(comma)-rpath$(comma)%,$(filter -L%,$(hdf5_words)))
endif

override FFLAGS += $(HDF5_FFLAGS)

.PHONY: hdf5-config h5export shape hdf5-version
hdf5-config:
	@echo 'HDF5 from:   $(firstword $(hdf5_found))'
	@echo 'HDF5_FFLAGS: $(HDF5_FFLAGS)'
	@echo 'HDF5_LIBS:   $(HDF5_LIBS)'

# ---- the code version, printed by impact --version and written into every
#      results file (src/system/build_info.f90): 'impact <VERSION> (git
#      <commit>[-dirty])' in a git checkout of this tree, 'impact <VERSION>'
#      without one (a source archive: git archive, a release tarball). The
#      release number is the file VERSION's; the commit git describe's, tags
#      left out (--exclude, git >= 2.13). Rewritten only when it changes.
$(BUILD)/code_version.inc: VERSION hdf5-version | $(BUILD)
	@v=$$(cat VERSION); \
	case "$$v" in [0-9]*) case "$$v" in *[!0-9A-Za-z.+-]*) v='';; esac;; *) v='';; esac; \
	if [ -z "$$v" ]; then echo 'VERSION: not a release number (as 1.2.0)' >&2; exit 1; fi; \
	g=''; if [ -e '$(CURDIR)/.git' ]; then \
	    g=$$(git -C '$(CURDIR)' describe --always --dirty --abbrev=7 --exclude='*' 2>/dev/null) || g=''; fi; \
	{ printf "   character(len=*), parameter :: code_release = '%s'\n" "$$v"; \
	  printf "   character(len=*), parameter :: code_version = 'impact %s%s'\n" "$$v" "$${g:+ (git $$g)}"; } > $@.tmp; \
	if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv $@.tmp $@; fi
$(BUILD)/build_info.o: $(BUILD)/code_version.inc

# ---- HDF5 -> gnuplot: the deflected shape at the peak force
H5EXPORT := $(BUILD)/h5export
SHAPE_PREFIX ?= out/clamped

h5export: $(H5EXPORT)
# tests/test_hdf5.pf runs the exporter
test-build: $(H5EXPORT)
$(H5EXPORT): tools/h5export.f90 $(TOOL_OBJS) $(LIB)
	$(FC_ALL) $< $(TOOL_OBJS) $(LIB) $(LIBS) -o $@

shape: $(H5EXPORT) impact
	@test -f '$(SHAPE_PREFIX).h5' || { test '$(SHAPE_PREFIX)' = out/clamped && ./impact input/clamped.nml > /dev/null; } \
	    || { echo 'make shape: $(SHAPE_PREFIX).h5 not found: run a deck with prefix = '\''$(SHAPE_PREFIX)'\'' first' >&2; exit 1; }
	$(H5EXPORT) '$(SHAPE_PREFIX).h5' -o '$(SHAPE_PREFIX)_shape.dat'
	gnuplot -e "prefix='$(SHAPE_PREFIX)'" postproc/shape.gp
	@echo 'plot written: $(SHAPE_PREFIX)_shape.png'
