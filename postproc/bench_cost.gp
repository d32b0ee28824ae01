# bench_cost.gp: CPU time per time step, and per plate solve, against the
# number of freedoms, log-log, with least-squares slopes (meshes with
# N >= 1000), from bench/results.dat (make bench): the short runs of the
# sweeps 'cost' (band) and 'cost_sky' (skyline), the paper scene, scheme 'fast'.
#
#   gnuplot -e "results='bench/results.dat'; outdir='docs/performance'" postproc/bench_cost.gp
#
# writes <outdir>/cost.png. Columns (see the header of results.dat): 2 sweep,
# 5 blas, 8 equations, 15 cpu_s, 17 setup_s, 18 step_ms, 20 plate_solves.
if (!exists("results")) results = 'bench/results.dat'
if (!exists("outdir")) outdir = 'docs/performance'
ok(sweep) = strcol(2) eq sweep && strcol(5) eq 'system' && strcol(30) eq 'ok'
step(sweep) = ok(sweep) ? column(18) : NaN
solve(sweep) = ok(sweep) ? (column(15) - column(17))/column(20)*1e3 : NaN
big(sweep, v) = (ok(sweep) && column(8) >= 1000) ? log(v) : NaN

set fit quiet
set fit logfile '/dev/null'
f1(x) = a1 + b1*x;  f2(x) = a2 + b2*x;  f3(x) = a3 + b3*x;  f4(x) = a4 + b4*x
fit f1(x) results using (big('cost', column(8))):(big('cost', column(18))) via a1, b1
fit f2(x) results using (big('cost_sky', column(8))):(big('cost_sky', column(18))) via a2, b2
fit f3(x) results using (big('cost', column(8))):(big('cost', (column(15) - column(17))/column(20)*1e3)) via a3, b3
fit f4(x) results using (big('cost_sky', column(8))):(big('cost_sky', (column(15) - column(17))/column(20)*1e3)) via a4, b4

set terminal pngcairo size 1300,560 font ",10"
set output outdir.'/cost.png'
set multiplot layout 1,2 title "Clamped nonlinear, scheme 'fast', 2.5 us, short runs (set-up excluded); fits over N >= 1000"
set logscale xy
set grid
set xlabel "freedoms N"
set key top left

set ylabel "CPU time per time step (ms)"
plot results using (ok('cost') ? column(8) : NaN):(step('cost')) with points pt 7 ps 1.3 title 'band (LAPACK dpbtrs)', \
     exp(a1)*x**b1 with lines lw 2 title sprintf('band: slope %.2f', b1), \
     results using (ok('cost_sky') ? column(8) : NaN):(step('cost_sky')) with points pt 5 ps 1.3 title 'skyline (own LDL^T)', \
     exp(a2)*x**b2 with lines lw 2 dt 2 title sprintf('skyline: slope %.2f', b2)

set ylabel "CPU time per plate solve (ms), the step's work divided by its solves"
plot results using (ok('cost') ? column(8) : NaN):(solve('cost')) with points pt 7 ps 1.3 title 'band', \
     exp(a3)*x**b3 with lines lw 2 title sprintf('band: slope %.2f', b3), \
     results using (ok('cost_sky') ? column(8) : NaN):(solve('cost_sky')) with points pt 5 ps 1.3 title 'skyline', \
     exp(a4)*x**b4 with lines lw 2 dt 2 title sprintf('skyline: slope %.2f', b4)
unset multiplot
