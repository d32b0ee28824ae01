# Fig. 8: a case whose deflection is small against the thickness, where the
# paper finds its nonlinear force close to a linear result (Sun & Chen's):
# simply supported, 243 g at 1 m/s, nonlinear against linear
# (input/paper/fig08_simply_supported_v1_*.nml).
fig = 'fig08';  W = 7.5;  H = 6.5
load 'postproc/paper_style.gp'
h_mm = 2.7
set multiplot layout 2,1 title "Fig. 8  Small deflection: simply supported, 243 g at 1 m/s, nonlinear against linear"
set xrange [0:3000]
set title '(a) contact force'
set ylabel 'contact force (N)'
plot hist('fig08_simply_supported_v1_linear') u 1:2 w l ls 2 t 'linear', \
     hist('fig08_simply_supported_v1_nonlinear') u 1:2 w l ls 1 t 'nonlinear'
set title '(b) plate centre deflection over the thickness'
set ylabel 'w / h'
plot hist('fig08_simply_supported_v1_linear') u 1:($4/h_mm) w l ls 2 t 'linear', \
     hist('fig08_simply_supported_v1_nonlinear') u 1:($4/h_mm) w l ls 1 t 'nonlinear'
unset multiplot
