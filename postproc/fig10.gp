# Fig. 10: clamped edges, nonlinear against linear, 243 g at 3 m/s
# (input/paper/fig10_clamped_*.nml): (a) contact force, (b) back-face y
# strain, (c) plate centre and impactor displacement, nonlinear, (d) the
# same, linear; the indentation is their difference (eq. 13).
fig = 'fig10';  W = 11.0;  H = 8.5
load 'postproc/paper_style.gp'
set multiplot layout 2,2 title "Fig. 10  Clamped edges, 243 g at 3 m/s"
set xrange [0:3000]
set title '(a) contact force'
set ylabel 'contact force (N)'
plot hist('fig10_clamped_linear') u 1:2 w l ls 2 t 'linear', \
     hist('fig10_clamped_nonlinear') u 1:2 w l ls 1 t 'nonlinear'
set title '(b) back-face strain ε_y at the Gauss point nearest the impact point'
set ylabel 'strain ε_y (10^{-6})'
plot hist('fig10_clamped_linear') u 1:($7*1e6) w l ls 2 t 'linear', \
     hist('fig10_clamped_nonlinear') u 1:($7*1e6) w l ls 1 t 'nonlinear'
set ylabel 'displacement (mm)'
set yrange [-4:2.5]
set key bottom left
do for [th in "nonlinear linear"] {
    set title '('.(th eq 'nonlinear' ? 'c' : 'd').') plate centre and impactor, '.th
    plot hist('fig10_clamped_'.th) u 1:4 w l ls 21 t 'plate at the impact point', \
         hist('fig10_clamped_'.th) u 1:5 w l ls 22 t 'impactor'
}
unset multiplot
