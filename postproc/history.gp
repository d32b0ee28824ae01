# history.gp: contact force, deflections, back-face strain and the energies
# against time from an impact history file (columns: see the file's '#'
# header).
#
#   gnuplot -e "prefix='out/clamped'" postproc/history.gp
#
# writes <prefix>_history.png. Column numbers: 1 time_us, 2 force_N,
# 4 w_plate_mm, 5 w_impactor_mm, 7 strain_y_back, 8 ke_impactor_J,
# 9 ke_plate_J, 10 strain_energy_J, 12 indentation_energy_J (the energy the
# contact took), 13 energy_error_J (what the integration lost, + , or
# created, -). The title names the scene (postproc/scene.gp, beside this
# script, reads the deck echo at the top of the history file).
if (!exists("prefix")) prefix = 'out/clamped'
file = prefix.'_history.dat'
# scene.gp is found beside this script (ARG0, gnuplot >= 5.4), else in postproc/
lastslash(s, i) = i < 1 ? 0 : (s[i:i] eq '/' ? i : lastslash(s, i - 1))
script_dir(s) = lastslash(s, strlen(s)) > 1 ? s[1:lastslash(s, strlen(s)) - 1] : (lastslash(s, strlen(s)) == 1 ? '/' : '.')
postproc = (exists("ARG0") && strlen(ARG0) > 0) ? script_dir(ARG0) : 'postproc'
set encoding utf8
load postproc.'/scene.gp'
set terminal pngcairo size 900,1400 font ",10"
set output prefix.'_history.png'
set multiplot layout 4,1 title scene font ",12" noenhanced
set lmargin 10
set rmargin 3
set grid
set xlabel "time (µs)"
set key top right

set ylabel "contact force (N)"
plot file using 1:2 with lines lw 2 title "F"

set ylabel "displacement (mm)"
plot file using 1:4 with lines lw 2 title "plate under the impactor, w", \
     file using 1:5 with lines lw 2 dt 2 title "impactor"

set ylabel "back-face strain y (µε)"
plot file using 1:($7*1e6) with lines lw 2 title "strain y, back face"

set ylabel "energy (J)"
set key below horizontal maxcols 3 width -2 spacing 1.1
set xlabel "time (µs)" offset 0,0.6
plot file using 1:8 with lines lw 2 lc rgb "#9400d3" title "kinetic, impactor", \
     file using 1:9 with lines lw 2 lc rgb "#009e73" title "kinetic, plate", \
     file using 1:10 with lines lw 2 lc rgb "#56b4e9" title "strain, plate", \
     file using 1:12 with lines lw 2 lc rgb "#e69f00" title "contact (indentation)", \
     file using 1:13 with lines lw 2 lc rgb "#d62728" title "lost (+) or created (−) by the integration", \
     file using 1:($8 + $9 + $10 + $12 + $13) with lines lw 1 dt 2 lc rgb "black" title "their sum, ½ m v₀²"
unset multiplot
