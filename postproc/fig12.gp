# Fig. 12: the same mass, 243 g, at 1, 2, 3, 4 m/s. Clamped, nonlinear
# (input/paper/fig12_v*.nml; 3 m/s is fig11_m0243). (b) the plate centre
# deflection divided by its largest value in the run, so that the curves
# compare in time.
fig = 'fig12';  W = 7.5;  H = 6.5
load 'postproc/paper_style.gp'
runs = "fig12_v1 fig12_v2 fig11_m0243 fig12_v4"
array wmax[4]
do for [i=1:4] {
    stats hist(word(runs,i)) u 4 nooutput
    wmax[i] = STATS_max
}
set multiplot layout 2,1 title "Fig. 12  The same mass, 243 g: clamped, nonlinear"
set xrange [0:4000]
set title '(a) contact force'
set ylabel 'contact force (N)'
plot for [i=1:4] hist(word(runs,i)) u 1:2 w l ls (10+i) t sprintf('%d m/s', i)
set title '(b) normalised plate centre deflection'
set ylabel 'w / w_{max}'
plot for [i=1:4] hist(word(runs,i)) u 1:($4/wmax[i]) w l ls (10+i) t sprintf('%d m/s (w_{max} = %.2f mm)', i, wmax[i])
unset multiplot
