# Fig. 6: convergence, clamped, nonlinear, 243 g at 3 m/s.
# (a) time step 10, 5, 2.5, 1 us on the 4 x 6 quarter mesh (fig06_4x6_dt*);
# (b, c) meshes 2 x 3, 4 x 6, 6 x 9, 8 x 12 at 2.5 us (fig06_2x3,
#        fig06_4x6_dt2p5, fig10_clamped_nonlinear, fig06_8x12);
# (d) the same four steps with the paper's literal update of the assumed
#     force, F_assum <- F_cont (./impact --set analysis.force_update=plain
#     on input/paper/update/clamped_4x6_dt*.nml; a run that diverged, its
#     energy error below -E0, stops there and is marked).
fig = 'fig06';  W = 11.0;  H = 8.5
load 'postproc/paper_style.gp'
steps = "10 5 2p5 1"
steplabel(s) = (s eq '2p5' ? '2.5' : s).' μs'
meshes = "2x3 4x6 6x9 8x12"
meshrun(m) = (m eq '4x6' ? 'fig06_4x6_dt2p5' : (m eq '6x9' ? 'fig10_clamped_nonlinear' : 'fig06_'.m))
upd(s) = run.'/update/clamped_4x6_dt'.s.'_fixed'
diverged(s) = system("awk -F' = ' '/^diverged_at_us/{print $2}' ".upd(s).'_summary.dat')

set multiplot layout 2,2 title "Fig. 6  Convergence: clamped, nonlinear, 243 g at 3 m/s"
set xrange [0:2000]
set ylabel 'contact force (N)'
set yrange [0:1800]
set title '(a) time step, 4×6 mesh (this code: bracketed update of the force)'
plot for [i=1:4] hist('fig06_4x6_dt'.word(steps,i)) u 1:2 w l ls (10+i) t 'Δt = '.steplabel(word(steps,i))
set title '(b) mesh, Δt = 2.5 μs: contact force'
plot for [i=1:4] hist(meshrun(word(meshes,i))) u 1:2 w l ls (10+i) t word(meshes,i).' mesh'
set title '(c) mesh, Δt = 2.5 μs: plate centre deflection'
set ylabel 'deflection (mm)'
set yrange [*:*]
set key bottom center
plot for [i=1:4] hist(meshrun(word(meshes,i))) u 1:4 w l ls (10+i) t word(meshes,i).' mesh'
set title "(d) time step, 4×6 mesh, the paper's literal update F_{assum} ← F_{cont}"
set ylabel 'contact force (N)'
set yrange [0:4000]
set key top right
plot for [i=1:4] upd(word(steps,i)).'_history.dat' u 1:2 w l ls (10+i) \
     t 'Δt = '.steplabel(word(steps,i)).(diverged(word(steps,i)) eq 'none' ? '' : \
       sprintf(': diverged at %.0f μs', real(diverged(word(steps,i)))))
unset multiplot
