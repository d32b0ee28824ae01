# Fig. 9: simply supported edges, nonlinear against linear, 243 g at 3 m/s
# (input/paper/fig09_simply_supported_*.nml): (a) contact force, (b) the
# in-plane y strain on the back face at the Gauss point nearest the impact
# point (history column 7).
fig = 'fig09';  W = 7.5;  H = 6.5
load 'postproc/paper_style.gp'
set multiplot layout 2,1 title "Fig. 9  Simply supported edges, 243 g at 3 m/s"
set xrange [0:3000]
set title '(a) contact force'
set ylabel 'contact force (N)'
plot hist('fig09_simply_supported_linear') u 1:2 w l ls 2 t 'linear', \
     hist('fig09_simply_supported_nonlinear') u 1:2 w l ls 1 t 'nonlinear'
set title '(b) back-face strain ε_y at the Gauss point nearest the impact point'
set ylabel 'strain ε_y (10^{-6})'
plot hist('fig09_simply_supported_linear') u 1:($7*1e6) w l ls 2 t 'linear', \
     hist('fig09_simply_supported_nonlinear') u 1:($7*1e6) w l ls 1 t 'nonlinear'
unset multiplot
