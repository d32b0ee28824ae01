# accuracy_plots.gp: check 12 of docs/VALIDATION.md, the error bars of
# impact --accuracy against the true errors (build/validation/accuracy_bounds.dat,
# written by validation/accuracy_validation.f90; columns: 1 scene,
# 2 result, 3 estimated, 4 true, 5 the reference's uncertainty, all
# relative to the result). Writes docs/validation/accuracy_bounds.png:
# every result of every scene, estimated against true error; a point
# below the diagonal would be a bound that fails.
file = 'build/validation/accuracy_bounds.dat'
set terminal pngcairo size 760,640 font ",10"
if (!exists('figdir')) figdir = 'out/docs/validation'
set output figdir.'/accuracy_bounds.png'
set logscale xy
set grid
set xrange [1e-7:10]
set yrange [1e-7:10]
set format x '10^{%T}'
set format y '10^{%T}'
set xlabel 'true error, relative (the reference''s uncertainty where larger)'
set ylabel 'estimated error, relative'
set key top left box opaque
set title 'impact --accuracy: the estimated error against the true error'
clip(x) = x < 1e-7 ? 1e-7 : x
max(a, b) = a > b ? a : b
plot x title 'estimated = true' lw 2 lc rgb '#444444', \
     10*x title 'estimated = 10 x true' dt 2 lc rgb '#888888', \
     file using (clip(max($4,$5))):(strcol(2) eq 'peak_force_N' ? clip($3) : NaN) pt 7 ps 1.2 title 'peak force', \
     '' using (clip(max($4,$5))):(strcol(2) eq 'max_deflection_mm' ? clip($3) : NaN) pt 5 ps 1.1 title 'max deflection', \
     '' using (clip(max($4,$5))):(strcol(2) eq 'contact_duration_us' ? clip($3) : NaN) pt 9 ps 1.3 title 'contact duration', \
     '' using (clip(max($4,$5))):(strcol(2) eq 'time_of_peak_us' ? clip($3) : NaN) pt 11 ps 1.3 title 'time of peak', \
     '' using (clip(max($4,$5))):(strcol(2) eq 'max_strain_y_back' ? clip($3) : NaN) pt 13 ps 1.3 title 'max back-face strain'
