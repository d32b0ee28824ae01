# Fig. 11: the same kinetic energy as 243 g at 3 m/s (1.0935 J): 0.1 kg at
# 4.6765 m/s, 0.243 kg at 3 m/s, 0.5 kg at 2.0914 m/s, 1 kg at 1.4789 m/s.
# Clamped, nonlinear (input/paper/fig11_m*.nml).
fig = 'fig11';  W = 7.5;  H = 6.5
load 'postproc/paper_style.gp'
runs = "fig11_m0100 fig11_m0243 fig11_m0500 fig11_m1000"
labels = "0.1_kg,_4.68_m/s 0.243_kg,_3_m/s 0.5_kg,_2.09_m/s 1_kg,_1.48_m/s"
label(i) = system("echo ".word(labels,i)." | tr _ ' '")
set multiplot layout 2,1 title "Fig. 11  The same kinetic energy, 1.09 J: clamped, nonlinear"
set xrange [0:4000]
set title '(a) contact force'
set ylabel 'contact force (N)'
plot for [i=1:4] hist(word(runs,i)) u 1:2 w l ls (10+i) t label(i)
set title '(b) back-face strain ε_y at the Gauss point nearest the impact point'
set ylabel 'strain ε_y (10^{-6})'
plot for [i=1:4] hist(word(runs,i)) u 1:($7*1e6) w l ls (10+i) t label(i)
unset multiplot
