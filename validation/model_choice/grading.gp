# Graded against uniform meshes (validation/model_choice/run.py writes
# grading.dat): the error of the peak force (signed: it changes sign) and
# |error| of the largest deflection, against the fine uniform reference,
# over the number of equations; runs
# whose eq. (19) iteration did not converge (column 10 = 0) are left out.
#   gnuplot -e "dir='docs/validation/model_choice'" validation/model_choice/grading.gp
if (!exists("dir")) dir = 'docs/validation/model_choice'
set terminal pngcairo size 1100,480 font ",10"
set output dir.'/grading.png'
set multiplot layout 1,2 title "Paper's clamped plate, 243 g at 3 m/s, nonlinear: error against the uniform 24 x 16 quarter"
set logscale x
set xlabel 'equations'
set grid
set key bottom right
set format y '%g'
set ylabel 'peak force error (%)'
set xzeroaxis lt -1
plot dir.'/grading.dat' using 5:(strcol(1) eq 'uniform' && $10 == 1 ? $8 : 1/0) with linespoints pt 7 title 'uniform', \
     '' using 5:(strcol(1) eq 'graded 1.25' && $10 == 1 ? $8 : 1/0) with linespoints pt 5 title 'graded, ratio 1.25', \
     '' using 5:(strcol(1) eq 'graded 1.5' && $10 == 1 ? $8 : 1/0) with linespoints pt 9 title 'graded, ratio 1.5'
set logscale y
set key top right
set ylabel '|max deflection error| (%)'
plot dir.'/grading.dat' using 5:(strcol(1) eq 'uniform' && $10 == 1 ? abs($9) : 1/0) with linespoints pt 7 title 'uniform', \
     '' using 5:(strcol(1) eq 'graded 1.25' && $10 == 1 ? abs($9) : 1/0) with linespoints pt 5 title 'graded, ratio 1.25', \
     '' using 5:(strcol(1) eq 'graded 1.5' && $10 == 1 ? abs($9) : 1/0) with linespoints pt 9 title 'graded, ratio 1.5'
unset multiplot
