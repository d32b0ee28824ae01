# make bench: the scaling table and the sweep throughput, and the
# speed-accuracy trade, measured (docs/PERFORMANCE.md).
#
#   make bench                   the parts scaling,sweep (under 10 minutes on 2
#                                cores): the scaling table (full plates 18x12 to
#                                150x150, s/step, peak memory, growth exponent) and
#                                the sweep throughput, printed and in their blocks
#                                of $(DOCS_DIR)/PERFORMANCE.md; scaling.dat beside
#                                $(BENCH_RESULTS)
#   make bench BENCH_PARTS=grid  the speed-accuracy grid (about 15 minutes on 2 cores);
#                                writes $(BENCH_RESULTS), $(DOCS_DIR)/performance/*.png
#                                and its block of $(DOCS_DIR)/PERFORMANCE.md
#                                (make docs: all three parts)
#   make bench BENCH_ARGS=--quick   small grids, to check the machinery
#                                (refused where the published results go)
#   make bench-kernels           build only the kernel timer
#
#   make bench-accuracy          the cost of impact --accuracy 0.05, 0.01, 0.002 on the
#                                paper's scenes (bench/accuracy_bench.py): out/bench/accuracy.dat
#                                and the bench-accuracy block of $(DOCS_DIR)/PERFORMANCE.md
#                                (DOCS_DIR=docs: bench/accuracy.dat and docs/PERFORMANCE.md);
#                                BENCH_ACCURACY_ARGS='--cap 300' sets the cap of each run
#
# DOCS_DIR (the top Makefile) is out/docs by default, and BENCH_RESULTS
# out/bench/results.dat: the checkout is left as it was. make docs sets
# DOCS_DIR=docs, and then BENCH_RESULTS is bench/results.dat: the published
# full-grid results, which the quick grid never overwrites
# (bench/run_bench.py refuses --quick there).
# Runs one job at a time (timings); BENCH_REPEAT=N sets the repeats (3).
# BENCH_OPENBLAS=<dir> adds runs with OpenBLAS (LD_LIBRARY_PATH).
BENCH_BUILD := $(BUILD)/bench
BENCH_ARGS ?=
BENCH_RESULTS ?= $(if $(docs_published),bench/results.dat,out/bench/results.dat)
BENCH_PARTS ?= $(if $(docs_published),scaling$(bench_comma)sweep$(bench_comma)grid,scaling$(bench_comma)sweep)
bench_comma := ,

.PHONY: bench bench-kernels bench-accuracy
bench: impact $(BENCH_BUILD)/bench_kernels
	$(PYTHON) bench/run_bench.py --parts '$(BENCH_PARTS)' $(BENCH_ARGS) --docs-dir '$(DOCS_DIR)' \
	    --results '$(BENCH_RESULTS)'

BENCH_ACCURACY_ARGS ?=
bench-accuracy: impact
	$(PYTHON) bench/accuracy_bench.py --docs-dir '$(DOCS_DIR)' $(BENCH_ACCURACY_ARGS)

bench-kernels: $(BENCH_BUILD)/bench_kernels

# The kernel timer links the library; its own loops (read rate, peak
# multiply-add rate) are compiled with -O3 -march=native to measure what this
# machine can do (the library keeps $(FFLAGS)).
$(BENCH_BUILD)/bench_kernels: bench/kernels.f90 $(LIB) mk/bench.mk
	@mkdir -p $(BENCH_BUILD)
	$(FC_ALL) -O3 -march=native $< $(LIB) $(LIBS) -o $@
