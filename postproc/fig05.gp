# Fig. 5: one quarter of the plate with D16 = D26 = 0 (the paper's model,
# section 3.1) against the full plate as laid up; linear theory, 243 g at
# 3 m/s; free, simply supported and clamped edges. Runs: input/paper/fig05_*.nml.
fig = 'fig05';  W = 7.5;  H = 9.0
load 'postproc/paper_style.gp'
set multiplot layout 3,1 title "Fig. 5  Quarter plate (D_{16} = D_{26} = 0, 6×9) against the full plate as laid up (12×18)\nlinear, 243 g at 3 m/s"
set ylabel 'contact force (N)'
set xrange [0:3000]
do for [e in "free simply_supported clamped"] {
    set title (e eq 'free' ? 'free edges' : (e eq 'clamped' ? 'clamped edges' : 'simply supported edges'))
    plot hist('fig05_full_'.e) u 1:2 w l ls 2 lw 3 dt 1 lc rgb '#f0a080' t 'full plate, D_{16}, D_{26} kept', \
         hist('fig05_quarter_'.e) u 1:2 w l ls 1 t 'quarter, D_{16} = D_{26} = 0'
}
unset multiplot
