# shape.gp: the deflected shape of the plate at the peak contact force, from
# the grid table that build/h5export writes out of a results file <prefix>.h5:
#
#   build/h5export out/clamped.h5 -o out/clamped_shape.dat
#   gnuplot -e "prefix='out/clamped'" postproc/shape.gp
#
# (or both at once: make shape SHAPE_PREFIX=out/clamped). Reads
# <prefix>_shape.dat (columns x_mm, y_mm, w_mm; one block of constant x per
# grid line) and writes <prefix>_shape.png: the surface w(x, y) coloured by w,
# w drawn downwards (the impactor moves towards +w), with its map below.
if (!exists("prefix")) prefix = 'out/clamped'
file = prefix.'_shape.dat'
set terminal pngcairo size 1000,750 font ",10"
set output prefix.'_shape.png'
set title "impact: deflection w at the peak force\n".file noenhanced
set xlabel "x (mm)"
set ylabel "y (mm)"
set zlabel "w (mm)" rotate by 90
set cblabel "w (mm)"
set zrange [*:*] reverse
set cbrange [*:*] reverse
set view 60, 30, 1, 1
set view equal xy
set ticslevel 0.2
set palette rgbformulae 33,13,10
set pm3d at bs
set grid
unset key
splot file using 1:2:3 with pm3d
