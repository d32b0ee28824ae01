# plots.gp: the figures of docs/VALIDATION.md, from the data that
# build/validate writes to build/validation/*.dat (make validate runs both).
#
#   gnuplot [-e "figdir='DIR'"] validation/plots.gp     (from the repository root)
#
# writes DIR/*.png (default out/docs/validation; make validate gives
# $(DOCS_DIR)/validation, docs/validation under make docs). Each data file
# names its columns in its '#' header.
d = 'build/validation/'
if (!exists("figdir")) figdir = 'out/docs/validation'
o = figdir.'/'
set terminal pngcairo size 900,600 font ",11"
set grid
set key top right

# ---- check 1: FE error against Navier against the mesh
set output o.'navier_convergence.png'
set title "Check 1: cross-ply [0/90/90/0], a/h = 10, simply supported: |FE / Navier - 1|"
set logscale xy
set format y "10^{%L}"
set xlabel "elements per half side (quarter model)"
set ylabel "relative error"
set xrange [0.8:20]
plot d.'navier_mesh.dat' u 1:2 w lp pt 7 lw 2 t "w centre, uniform load", \
     d.'navier_mesh.dat' u 1:3 w lp pt 5 lw 2 t "w centre, sinusoidal load", \
     d.'navier_mesh.dat' u 1:($4 > 0 ? $4 : 1/0) w lp pt 9 lw 2 t "(1,1) frequency", \
     3.3e-2*x**(-4) w l dt 2 lc rgb "black" t "slope -4"
unset logscale
set format y "%g"
set autoscale

# ---- check 3: no shear locking
set output o.'locking.png'
set title "Check 3: simply supported isotropic square plate, uniform load, quarter 4 x 4"
set logscale x
set xlabel "a/h"
set ylabel "w centre / w classical plate"
set key bottom left
plot d.'locking.dat' u 1:5 w lp pt 9 lw 2 t "FE, MITC9 (the default)", \
     d.'locking.dat' u 1:2 w lp pt 7 lw 2 t "FE, selective 2 x 2 shear (the paper's rule)", \
     d.'locking.dat' u 1:3 w lp pt 5 lw 2 t "FE, full 3 x 3 shear", \
     d.'locking.dat' u 1:4 w l lw 2 dt 2 t "Navier, FSDT (exact)"
unset logscale
set key top right

# ---- check 4: the nonlinear strip
set output o.'strip.png'
set title "Check 4: strip with immovable edges (TWK Arts. 2-3), nu = 0.3"
set xlabel "Q = q l^4 / (E h^4)"
set ylabel "w0 / h"
set xrange [0:400]
set yrange [0:3.5]
set key top left
plot d.'strip.dat' u 1:2 w l lw 2 lc rgb "blue" t "simply supported, TWK", \
     d.'strip.dat' every 20 u 1:3 w p pt 7 ps 1.2 lc rgb "blue" t "simply supported, FE", \
     d.'strip.dat' u 1:4 w l lw 2 lc rgb "red" t "built in, TWK", \
     d.'strip.dat' every 20 u 1:5 w p pt 5 ps 1.2 lc rgb "red" t "built in, FE", \
     d.'strip.dat' u 1:6 w l dt 2 lc rgb "blue" t "simply supported, linear", \
     d.'strip.dat' u 1:7 w l dt 2 lc rgb "red" t "built in, linear"
set autoscale
set key top right

# ---- check 5: step pressure
set output o.'transient.png'
set terminal pngcairo size 900,800 font ",11"
set multiplot layout 2,1 title "Check 5: step pressure on the simply supported cross-ply plate, a/h = 10"
set xlabel "time (ms)"
set ylabel "centre deflection (mm)"
set title "sinusoidal pressure: FE with T11/dt = 10 and 320, Navier (modal)"
plot d.'transient_sin_1.dat' u 1:3 w l lw 3 lc rgb "gray" t "Navier", \
     d.'transient_sin_1.dat' u 1:2 w lp pt 7 lw 1 t "FE, T11/dt = 10", \
     d.'transient_sin_6.dat' u 1:2 w l lw 1 dt 2 lc rgb "black" t "FE, T11/dt = 320"
set title "uniform pressure: FE (quarter 16 x 16, T11/dt = 800), Navier series"
plot d.'transient_uniform.dat' u 1:3 w l lw 3 lc rgb "gray" t "Navier", \
     d.'transient_uniform.dat' u 1:2 w l lw 1 lc rgb "black" t "FE"
unset multiplot
set terminal pngcairo size 900,600 font ",11"

set output o.'transient_convergence.png'
set title "Check 5: Newmark's average acceleration rule, sinusoidal step pressure"
set logscale xy
set format y "10^{%L}"
set xlabel "T11 / dt"
set ylabel "max |w FE - w Navier| / max |w Navier|, 0 < t < 2 T11"
plot d.'transient_dt.dat' u 1:3 w lp pt 7 lw 2 t "FE, quarter 8 x 8", \
     17.3*x**(-2) w l dt 2 lc rgb "black" t "slope -2"
unset logscale
set format y "%g"

# ---- check 7: the paper's Fig. 5
set output o.'fig5.png'
set terminal pngcairo size 900,1100 font ",10"
set multiplot layout 3,1 title "Check 7, the paper's Fig. 5: 243 g at 3 m/s, linear"
set xlabel "time (us)"
set ylabel "contact force (N)"
do for [e in "clamped simply_supported free"] {
   set title e." edges" noenhanced
   plot d.'fig5_quarter_'.e.'.dat' u 1:2 w l lw 3 lc rgb "gray" t "quarter, D16 = D26 = 0", \
        d.'fig5_full_drop_'.e.'.dat' u 1:2 w l lw 1 dt 2 lc rgb "black" t "full, D16 = D26 = 0", \
        d.'fig5_full_'.e.'.dat' u 1:2 w l lw 1.5 lc rgb "red" t "full, as laid up"
}
unset multiplot
set terminal pngcairo size 900,600 font ",11"

# ---- check 8: the force-indentation loop
set output o.'energy_loop.png'
set title "Check 8: force against indentation, the paper's law, clamped, von Karman"
set xlabel "indentation (mm)"
set ylabel "contact force (N)"
set key top left
plot d.'energy_loop.dat' u 1:2 w l lw 2 t "./impact history"

# ---- check 10: the first contact against the modal solution
set output o.'point_response.png'
set title "Check 10: simply supported plate, linear, 243 g at 3 m/s: the first contact"
set xlabel "time (μs)"
set ylabel "contact force (N)"
set key top right
set xrange [0:420]
set yrange [0:600]
plot d.'point_response_modal.dat' u 1:2 w l lw 3 lc rgb "black" t "Navier modal solution, Hertz load", \
     d.'point_response_converged_9x6_history.dat' u 1:2 w l lw 2 t "MITC9, Hertz load, quarter 9 x 6", \
     d.'point_response_converged_36x24_history.dat' u 1:2 w l lw 2 dt 2 t "MITC9, Hertz load, quarter 36 x 24", \
     d.'point_response_paper_9x6_history.dat' u 1:2 w l lw 2 t "2 x 2 shear, point force (the paper's), 9 x 6", \
     d.'point_response_paper_36x24_history.dat' u 1:2 w l lw 2 dt 2 t "2 x 2 shear, point force (the paper's), 36 x 24"
set autoscale

# ---- check 11: ply stresses against the mesh
set output o.'ply_stress_convergence.png'
set title "Check 11: ply stresses, a/h = 10, sinusoidal load: largest |FE - exact| / max |exact|"
set logscale xy
set format y "10^{%L}"
set xlabel "elements per half side (quarter model)"
set ylabel "relative error"
set key top right
set xrange [3:40]
plot d.'ply_stress_mesh.dat' u 1:2 w lp pt 7 lw 2 t "cross-ply: s11 (in-plane)", \
     d.'ply_stress_mesh.dat' u 1:6 w lp pt 5 lw 2 t "cross-ply: t13 (equilibrium)", \
     d.'ply_stress_mesh.dat' u 1:5 w lp pt 4 lw 2 t "cross-ply: t23 (equilibrium)", \
     d.'ply_stress_mesh.dat' u 1:7 w lp pt 9 lw 2 t "isotropic: s11", \
     d.'ply_stress_mesh.dat' u 1:11 w lp pt 11 lw 2 t "isotropic: t13", \
     0.1*x**(-2) w l dt 2 lc rgb "black" t "slope -2", \
     0.55*x**(-1) w l dt 3 lc rgb "black" t "slope -1"
unset logscale
set format y "%g"
set autoscale
