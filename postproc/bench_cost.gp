# bench_cost.gp: CPU time per time step against the number of freedoms,
# log-log, with the least-squares slope (meshes with N >= 1000), from
# bench/results.dat (make bench): the short runs of the sweeps 'cost' (band)
# and 'cost_sky' (skyline), the paper scene, scheme 'fast'.
#
#   gnuplot -e "results='bench/results.dat'; outdir='docs/performance'" postproc/bench_cost.gp
#
# writes <outdir>/cost.png. Columns (see the header of results.dat): 2 sweep,
# 5 blas, 8 equations, 18 step_ms.
if (!exists("results")) results = 'bench/results.dat'
if (!exists("outdir")) outdir = 'docs/performance'
sel(sweep, col) = (strcol(2) eq sweep && strcol(5) eq 'system') ? column(col) : NaN
big(sweep, col) = (strcol(2) eq sweep && strcol(5) eq 'system' && column(8) >= 1000) ? log(column(col)) : NaN

set fit quiet
set fit logfile '/dev/null'
fb(x) = ab + bb*x
fs(x) = as + bs*x
fit fb(x) results using (big('cost', 8)):(big('cost', 18)) via ab, bb
fit fs(x) results using (big('cost_sky', 8)):(big('cost_sky', 18)) via as, bs

set terminal pngcairo size 900,650 font ",10"
set output outdir.'/cost.png'
set logscale xy
set grid
set xlabel "freedoms N"
set ylabel "CPU time per time step (ms)"
set key top left
set title "Cost per step, clamped nonlinear, scheme 'fast', 2.5 us (short runs; set-up excluded)"
plot results using (sel('cost', 8)):(sel('cost', 18)) with points pt 7 ps 1.3 title 'band (LAPACK dpbtrs)', \
     exp(ab)*x**bb with lines lw 2 title sprintf('band fit: slope %.2f', bb), \
     results using (sel('cost_sky', 8)):(sel('cost_sky', 18)) with points pt 5 ps 1.3 title 'skyline (own LDL^T)', \
     exp(as)*x**bs with lines lw 2 dt 2 title sprintf('skyline fit: slope %.2f', bs)
