# impact — nonlinear low-velocity impact of composite laminates (Choi, Hong & Lee 1991)
#
#   make            build ./impact
#   make run        install what is missing, build, run input/clamped.nml, plot it
#   make test       install what is missing, build, run the pFUnit tests
#   make setup      only the Debian packages (tools/setup-debian)
#   make clean
#
# Compiler settings can be overridden: make FC=gfortran FFLAGS='-O3 ...'

FC      ?= gfortran
ifeq ($(FC),f77)
FC      := gfortran
endif
BUILD   := build
FFLAGS  ?= -O2 -g
FSTD    := -std=f2008 -Wall -fimplicit-none
LAPACK  ?= -llapack -lblas
FC_ALL   = $(FC) $(FSTD) $(FFLAGS) -J$(BUILD) -I$(BUILD)

# Modules in dependency order, one module per file, named after the module.
MODULES := kinds materials gauss_rules shape_functions mesh element_matrices \
           band_matrix skyline_matrix global_matrix contact_law newmark \
           input_deck output_files impact_driver
OBJS    := $(patsubst %,$(BUILD)/%.o,$(MODULES))
LIB     := $(BUILD)/libimpact.a

.PHONY: all run test setup clean plot
all: impact

$(BUILD):
	@mkdir -p $(BUILD)

# Each module depends on every module before it (simple and always right).
$(BUILD)/%.o: src/%.f90 | $(BUILD)
	$(FC_ALL) -c $< -o $@

define chain
$(BUILD)/$(word 2,$(1)).o: $(BUILD)/$(word 1,$(1)).o
endef
$(foreach i,$(shell seq 2 $(words $(MODULES))),$(eval $(call chain,$(word $(shell expr $(i) - 1),$(MODULES)) $(word $(i),$(MODULES)))))

$(LIB): $(OBJS)
	ar rcs $@ $^

impact: src/impact.f90 $(LIB)
	$(FC_ALL) src/impact.f90 $(LIB) $(LAPACK) -o $@

setup:
	@sh tools/setup-debian

run: setup impact
	@mkdir -p out
	./impact < input/clamped.nml
	gnuplot -e "prefix='out/clamped'" postproc/history.gp
	@echo "plot written: out/clamped_history.png"

clean:
	rm -rf $(BUILD) impact

-include tests/tests.mk
