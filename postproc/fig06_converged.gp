# Fig. 6 with a converged model (docs/PAPER.md, "With a converged model"):
# the mesh study of the paper's model (its 2x2 shear rule and point force,
# input/paper/) beside that of the converged model (MITC9 shear, Hertz's
# contact load, input/paper/converged/), clamped, 243 g at 3 m/s, 2.5 us:
# (a, b) contact force and (c, d) plate deflection under the impactor near
# its largest (a close-up: the whole history is Fig. 6c), nonlinear, quarter
# meshes 2 x 3 ... 24 x 36; (e, f) contact force, linear, 6 x 9, 12 x 18,
# 24 x 36 (each halves the element), in the colours of (a, b).
fig = 'fig06_converged';  W = 11.0;  H = 12.0
load 'postproc/paper_style.gp'
# six meshes: the four of paper_style.gp and two more
set style line 15 lc rgb '#d04010' lw 2 dt 1
set style line 16 lc rgb '#202020' lw 1.5 dt 1
meshes = "2x3 4x6 6x9 8x12 12x18 24x36"
meshlabel(m) = m[1:strstrt(m,'x')-1].'×'.m[strstrt(m,'x')+1:].' mesh'
paper_run(m) = (m eq '4x6' ? 'fig06_4x6_dt2p5' : (m eq '6x9' ? 'fig10_clamped_nonlinear' : \
                (m eq '12x18' ? 'fig10_clamped_nonlinear_12x18' : 'fig06_'.m)))
conv_run(m) = 'converged/'.(m eq '6x9' ? 'fig10_clamped_nonlinear' : \
                (m eq '12x18' ? 'fig10_clamped_nonlinear_12x18' : 'fig06_'.m))
linmeshes = "6x9 12x18 24x36"
lin_run(pre, m) = pre.'fig10_clamped_linear'.(m eq '6x9' ? '' : '_'.m)

set multiplot layout 3,2 title "Fig. 6 with a converged model: clamped, 243 g at 3 m/s, Δt = 2.5 μs"
set xrange [0:2000]
set ylabel 'contact force (N)'
set yrange [0:1900]
set title "(a) the paper's model (2×2 shear, point force): contact force, nonlinear"
plot for [i=1:6] hist(paper_run(word(meshes,i))) u 1:2 w l ls (10+i) t meshlabel(word(meshes,i))
set title '(b) the converged model (MITC9, Hertz load): contact force, nonlinear'
plot for [i=1:6] hist(conv_run(word(meshes,i))) u 1:2 w l ls (10+i) t meshlabel(word(meshes,i))
set ylabel 'deflection under the impactor (mm)'
set xrange [600:1200]
set yrange [1.50:1.64]
set key top right maxrows 6
set title "(c) the paper's model: plate deflection near its largest, nonlinear"
plot for [i=1:6] hist(paper_run(word(meshes,i))) u 1:4 w l ls (10+i) t meshlabel(word(meshes,i))
set title '(d) the converged model: plate deflection near its largest, nonlinear'
plot for [i=1:6] hist(conv_run(word(meshes,i))) u 1:4 w l ls (10+i) t meshlabel(word(meshes,i))
set ylabel 'contact force (N)'
set xrange [0:2000]
set yrange [0:1900]
set key top right maxrows 6
linls = "13 15 16"
set title "(e) the paper's model: contact force, linear"
plot for [i=1:3] hist(lin_run('', word(linmeshes,i))) u 1:2 w l ls int(word(linls,i)) t meshlabel(word(linmeshes,i))
set title '(f) the converged model: contact force, linear'
plot for [i=1:3] hist(lin_run('converged/', word(linmeshes,i))) u 1:2 w l ls int(word(linls,i)) t meshlabel(word(linmeshes,i))
unset multiplot
