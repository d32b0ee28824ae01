# paper_style.gp: terminal, colours and helpers shared by the figures of the
# paper, postproc/fig05.gp ... fig13.gp (`make figures`, mk/figures.mk).
#
# The figure script sets, before `load 'postproc/paper_style.gp'`:
#   fig    the figure's name ('fig05'), W, H  its size in inches;
# the command line may set (make figures does):
#   fmt    'png' (default) or 'pdf'
#   run    directory of the runs (default 'out/paper': prefix of every deck
#          of input/paper/ is out/paper/<deck name>)
#   figdir where the figure goes (default 'docs/figures')
# Column numbers of a history file (its '#' header names them with units):
#   1 time_us, 2 force_N, 3 indentation_mm, 4 w_plate_mm, 5 w_impactor_mm,
#   7 strain_y_back.
if (!exists("fmt")) fmt = 'png'
if (!exists("run")) run = 'out/paper'
if (!exists("figdir")) figdir = 'docs/figures'
if (fmt eq 'pdf') {
    set terminal pdfcairo enhanced size W, H font "sans,9" linewidth 1
} else {
    set terminal pngcairo enhanced size int(W*110), int(H*110) font "sans,10" linewidth 1
}
set output figdir.'/'.fig.'.'.fmt

# the history file of the deck input/paper/<name>.nml
hist(name) = run.'/'.name.'_history.dat'

set grid lc rgb '#d8d8d8'
set key top right opaque box lc rgb '#bbbbbb' samplen 2.5
set xlabel 'time (μs)'
set format y '%g'
set mxtics 2
set mytics 2
# nonlinear, linear (two-curve comparisons)
set style line 1 lc rgb '#0060b0' lw 2 dt 1
set style line 2 lc rgb '#d04010' lw 2 dt 2
# series of four (fig. 6, 11-13)
set style line 11 lc rgb '#7a3fb0' lw 2 dt 1
set style line 12 lc rgb '#009e73' lw 2 dt 1
set style line 13 lc rgb '#0060b0' lw 2 dt 1
set style line 14 lc rgb '#e69f00' lw 2 dt 1
# displacements (fig. 7, 10)
set style line 21 lc rgb '#0060b0' lw 2 dt 1
set style line 22 lc rgb '#404040' lw 2 dt 4
