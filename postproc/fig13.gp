# Fig. 13: the same velocity, 3 m/s, with 0.1, 0.243, 0.5, 1 kg. Clamped,
# nonlinear (input/paper/fig13_m*.nml; 0.243 kg is fig11_m0243). (b) the
# plate centre deflection divided by its largest value in the run.
fig = 'fig13';  W = 7.5;  H = 6.5
load 'postproc/paper_style.gp'
runs = "fig13_m0100 fig11_m0243 fig13_m0500 fig13_m1000"
masses = "0.1 0.243 0.5 1"
array wmax[4]
do for [i=1:4] {
    stats hist(word(runs,i)) u 4 nooutput
    wmax[i] = STATS_max
}
set multiplot layout 2,1 title "Fig. 13  The same velocity, 3 m/s: clamped, nonlinear"
set xrange [0:5000]
set title '(a) contact force'
set ylabel 'contact force (N)'
plot for [i=1:4] hist(word(runs,i)) u 1:2 w l ls (10+i) t word(masses,i).' kg'
set title '(b) normalised plate centre deflection'
set ylabel 'w / w_{max}'
plot for [i=1:4] hist(word(runs,i)) u 1:($4/wmax[i]) w l ls (10+i) t sprintf('%s kg (w_{max} = %.2f mm)', word(masses,i), wmax[i])
unset multiplot
