# accuracy.gp: the convergence of an accuracy run (impact --accuracy TOL),
# from <prefix>_accuracy.dat (one row per run; its '#' header names the
# columns and their units).
#
#   gnuplot -e "prefix='out/clamped'" postproc/accuracy.gp
#
# writes <prefix>_accuracy.png: for each result a row of two panels, the
# result against the time step (the time axis of the ladder: dt, dt/2,
# dt/4, ... on mesh level 0) and against the element size (the mesh axis,
# 1/sqrt(nx ny) relative to level 0, at dt), each run with the part of its
# estimated error that the axis gives (the time part, the mesh part) as an
# error bar; the run whose results the summary gives is the large red
# point, with its whole error. Columns: 2 role, 5 dt_us, 9 element_size_rel,
# 11 chosen, 12 state, 13-19 the results, 20-26 their errors, 27-33 the
# time parts, 34-40 the mesh parts.
if (!exists("prefix")) prefix = 'out/clamped'
file = prefix.'_accuracy.dat'
names = "peak_force_N max_deflection_mm contact_duration_us time_of_peak_us max_strain_y_back max_failure_index damage_dissipated_J"
labels = "'peak force (N)' 'max deflection (mm)' 'contact duration (us)' 'time of peak (us)' 'max back-face strain y' 'max failure index' 'damage dissipated (J)'"

# the results the file has (the failure index only with &strength, the dissipated energy with ply damage)
n = 0
do for [i=1:7] {
    stats file using (strcol(12) eq 'done' ? column(12+i) : NaN) nooutput
    if (exists("STATS_records")) { if (STATS_records > 0) { n = i } }
}

set terminal pngcairo size 1000, 260*n font ",9"
set output prefix.'_accuracy.png'
set multiplot layout n, 2 title "impact --accuracy: ".file noenhanced
set grid
set logscale x 2
set key top right opaque samplen 1
set bars small
set offsets graph 0.05, graph 0.05, graph 0.1, graph 0.1
# the time axis: role 'time' (mesh level 0); the mesh axis: role 'mesh' and
# the run of both levels 0 (role 'time', time level 0)
on_axis(role) = strcol(12) eq 'done' && (strcol(2) eq role || (role eq 'mesh' && strcol(2) eq 'time' && $3 == 0))
do for [i=1:n] {
    v = 12 + i
    e = 19 + i
    et = 26 + i
    em = 33 + i
    set ylabel word(labels, i) noenhanced
    set xlabel "time step dt (us), mesh level 0"
    plot file using (on_axis('time') ? $5 : NaN):v:(column(et) == column(et) ? column(et) : 0) \
              with yerrorbars pt 7 ps 0.8 lc rgb '#1f77b4' title 'time axis, time part', \
         '' using (on_axis('time') ? $5 : NaN):v with lines lc rgb '#1f77b4' notitle, \
         '' using ($11 == 1 ? $5 : NaN):v:(column(e)) with yerrorbars pt 7 ps 1.6 lc rgb '#d62728' \
              title 'run chosen, whole error'
    set xlabel "element size 1/sqrt(nx ny), relative to mesh level 0"
    plot file using (on_axis('mesh') ? $9 : NaN):v:(column(em) == column(em) ? column(em) : 0) \
              with yerrorbars pt 7 ps 0.8 lc rgb '#2ca02c' title 'mesh axis, mesh part', \
         '' using (on_axis('mesh') ? $9 : NaN):v with lines lc rgb '#2ca02c' notitle, \
         '' using ($11 == 1 ? $9 : NaN):v:(column(e)) with yerrorbars pt 7 ps 1.6 lc rgb '#d62728' \
              title 'run chosen, whole error'
}
unset multiplot
