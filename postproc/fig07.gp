# Fig. 7: free edges, nonlinear, 243 g at 3 m/s (input/paper/fig07_free_nonlinear.nml).
# The paper compares its force with Tan & Sun's measurement (NASA CR-168057);
# that data, and the impact conditions of that test, are not available here:
# the figure shows this code's response alone.
fig = 'fig07';  W = 7.5;  H = 6.5
load 'postproc/paper_style.gp'
set multiplot layout 2,1 title "Fig. 7  Free edges, nonlinear, 243 g at 3 m/s\n(the paper's experimental curve, Tan and Sun, NASA CR-168057, is not available: not shown)"
set xrange [0:1500]
set title '(a) contact force'
set ylabel 'contact force (N)'
plot hist('fig07_free_nonlinear') u 1:2 w l ls 1 t 'this code'
set title '(b) plate centre and impactor'
set ylabel 'displacement (mm)'
set key top left
plot hist('fig07_free_nonlinear') u 1:4 w l ls 21 t 'plate at the impact point', \
     hist('fig07_free_nonlinear') u 1:5 w l ls 22 t 'impactor'
unset multiplot
