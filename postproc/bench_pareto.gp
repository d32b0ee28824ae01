# bench_pareto.gp: error against CPU time from bench/results.dat (make bench),
# one curve per knob, log-log.
#
#   gnuplot -e "results='bench/results.dat'; outdir='docs/performance'" postproc/bench_pareto.gp
#
# writes <outdir>/pareto.png (the paper scene CN: one panel per error measure)
# <outdir>/scenes.png (the four scenes: the largest of the three errors) and
# <outdir>/knobs.png (6x9 runs: time step and tolerances, mesh error excluded).
# Columns of results.dat (see its header): 1 scene, 2 sweep, 15 cpu_s,
# 26 err_peak, 27 err_duration, 28 err_deflection, 29 err_max. The sweep
# mesh_1991 is the paper's model (2x2 shear, point force) against the
# converged model's reference: its error does not go to zero.
if (!exists("results")) results = 'bench/results.dat'
if (!exists("outdir")) outdir = 'docs/performance'

# the knobs: sweep name in column 2 and the curve's title
sweeps = "mesh mesh_sky mesh_paper dt dt_paper cr2 cr2_paper cr1_paper mesh_dt mesh_1991"
titles = "'mesh (fast, band)' 'mesh (fast, skyline)' 'mesh (paper)' 'time step (fast)' 'time step (paper)' 'cr2 (fast)' 'cr2 (paper)' 'cr1 (paper)' 'mesh 8x12, 12x18 at 1.25 us (fast)' 'mesh, the paper model (2x2 shear, point force)'"
sel(scene, sweep, col) = (strcol(1) eq scene && strcol(2) eq sweep && strcol(5) eq 'system' && strcol(30) eq 'ok') ? column(col) : NaN

# common ranges, so that a panel without data (a smaller grid) still draws
stats results using 15 nooutput
xlo = STATS_min/2.0;  xhi = STATS_max*2.0
set xrange [xlo:xhi]
set yrange [1e-6:1]

set terminal pngcairo size 1500,520 font ",10"
set output outdir.'/pareto.png'
set logscale xy
set grid
set format y "10^{%T}"
set xlabel "CPU time per run (s, median)"
set key bottom left font ",8"
set multiplot layout 1,3 title "Error against CPU time, clamped nonlinear (the paper scene, 2.1 ms): one curve per knob, the others at 6x9, 2.5 us, cr1 = 2e-3, cr2 = 1e-7, fast, band"
do for [m = 1:3] {
    col = 25 + m
    set ylabel word("'relative error of the peak force' 'relative error of the first-contact duration' 'relative error of the max deflection'", m)
    plot for [i = 1:words(sweeps)] results using (sel('CN', word(sweeps, i), 15)):(sel('CN', word(sweeps, i), col)) \
         with linespoints pt i lw 1.5 title word(titles, i)
}
unset multiplot

set terminal pngcairo size 1200,900 font ",10"
set output outdir.'/scenes.png'
set multiplot layout 2,2 title "Largest of the three relative errors (peak force, first contact, max deflection) against CPU time"
scenes = "CN CL SN SL"
stitles = "'clamped, nonlinear (2.1 ms)' 'clamped, linear (2.1 ms)' 'simply supported, nonlinear (1.7 ms)' 'simply supported, linear (1.7 ms)'"
set ylabel "largest relative error"
do for [k = 1:4] {
    set title word(stitles, k)
    plot for [i = 1:words(sweeps)] results using (sel(word(scenes, k), word(sweeps, i), 15)):(sel(word(scenes, k), word(sweeps, i), 29)) \
         with linespoints pt i lw 1.5 title word(titles, i)
}
unset multiplot

# the time step and the tolerances alone: 6x9 runs against the 6x9 mesh's own
# limit (column 34, err6_max), which leaves out the mesh error
set terminal pngcairo size 1200,900 font ",10"
set output outdir.'/knobs.png'
set yrange [1e-7:1]
set multiplot layout 2,2 title "6x9 mesh: the error of the time step and the tolerances alone (against the 6x9 mesh's converged answer), largest of the three"
ksweeps = "dt dt_paper cr2 cr2_paper cr1_paper"
ktitles = "'time step (fast)' 'time step (paper)' 'cr2 (fast)' 'cr2 (paper)' 'cr1 (paper)'"
set ylabel "largest relative error, mesh error excluded"
do for [k = 1:4] {
    set title word(stitles, k)
    plot for [i = 1:words(ksweeps)] results using (sel(word(scenes, k), word(ksweeps, i), 15)):(sel(word(scenes, k), word(ksweeps, i), 34)) \
         with linespoints pt i+3 lw 1.5 title word(ktitles, i)
}
unset multiplot
