# Fig. 9a and 10a with a converged model (docs/PAPER.md, "With a converged
# model"): contact force, nonlinear against linear, on the paper's 6 x 9
# quarter mesh and on 12 x 18, with the paper's model (its 2x2 shear rule and
# point force, input/paper/) and with the converged model (MITC9 shear,
# Hertz's contact load, input/paper/converged/); 243 g at 3 m/s, 2.5 us.
# (a, b) simply supported edges, (c, d) clamped edges, (e, f) the end of
# the simply supported plate's first contact, close up, the force on a log
# scale: a gap in a curve is a separation (F = 0).
fig = 'fig09_10_converged';  W = 11.0;  H = 12.0
load 'postproc/paper_style.gp'
# nonlinear blue, linear red; 6 x 9 solid, 12 x 18 dashed
set style line 31 lc rgb '#0060b0' lw 2 dt 1
set style line 32 lc rgb '#d04010' lw 2 dt 1
set style line 33 lc rgb '#00a0e0' lw 1.5 dt 2
set style line 34 lc rgb '#f08040' lw 1.5 dt 2
set multiplot layout 3,2 title "Fig. 9a and 10a with a converged model: 243 g at 3 m/s, two meshes"
set xrange [0:3000]
set ylabel 'contact force (N)'
do for [s in "fig09_simply_supported fig10_clamped"] {
    set yrange [0:(s eq 'fig10_clamped' ? 1900 : 1700)]
    do for [pre in "paper converged"] {
        p = (pre eq 'paper' ? '' : 'converged/')
        set title sprintf("(%s) %s, %s", \
            (s eq 'fig10_clamped' ? (pre eq 'paper' ? 'c' : 'd') : (pre eq 'paper' ? 'a' : 'b')), \
            (s eq 'fig10_clamped' ? 'clamped' : 'simply supported'), \
            (pre eq 'paper' ? "the paper's model (2×2 shear, point force)" : 'the converged model (MITC9, Hertz load)'))
        plot hist(p.s.'_nonlinear') u 1:2 w l ls 31 t 'nonlinear, 6×9', \
             hist(p.s.'_linear') u 1:2 w l ls 32 t 'linear, 6×9', \
             hist(p.s.'_nonlinear_12x18') u 1:2 w l ls 33 t 'nonlinear, 12×18', \
             hist(p.s.'_linear_12x18') u 1:2 w l ls 34 t 'linear, 12×18'
    }
}
set xrange [280:440]
set logscale y
set yrange [0.1:500]
set format y '%g'
set key bottom left
do for [pre in "paper converged"] {
    p = (pre eq 'paper' ? '' : 'converged/')
    s = 'fig09_simply_supported'
    set title sprintf("(%s) simply supported, %s: the end of the first contact (log scale)", (pre eq 'paper' ? 'e' : 'f'), \
        (pre eq 'paper' ? "the paper's model" : 'the converged model'))
    plot hist(p.s.'_nonlinear') u 1:2 w l ls 31 t 'nonlinear, 6×9', \
         hist(p.s.'_linear') u 1:2 w l ls 32 t 'linear, 6×9', \
         hist(p.s.'_nonlinear_12x18') u 1:2 w l ls 33 t 'nonlinear, 12×18', \
         hist(p.s.'_linear_12x18') u 1:2 w l ls 34 t 'linear, 12×18'
}
unset multiplot
