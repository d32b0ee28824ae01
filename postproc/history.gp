# history.gp: contact force, deflections and back-face strain against time
# from an impact history file (columns: see the file's '#' header).
#
#   gnuplot -e "prefix='out/clamped'" postproc/history.gp
#
# writes <prefix>_history.png. Column numbers: 1 time_us, 2 force_N,
# 4 w_plate_mm, 5 w_impactor_mm, 7 strain_y_back.
if (!exists("prefix")) prefix = 'out/clamped'
file = prefix.'_history.dat'
set terminal pngcairo size 900,1100 font ",10"
set output prefix.'_history.png'
set multiplot layout 3,1 title "impact: ".file noenhanced
set grid
set xlabel "time (us)"
set key top right

set ylabel "contact force (N)"
plot file using 1:2 with lines lw 2 title "F"

set ylabel "displacement (mm)"
plot file using 1:4 with lines lw 2 title "plate centre w", \
     file using 1:5 with lines lw 2 dt 2 title "impactor"

set ylabel "back-face strain y (micro)"
plot file using 1:($7*1e6) with lines lw 2 title "strain y, back face"
unset multiplot
