# damage_map.gp: the damage map of a run with &strength, ply by ply: the
# largest failure index of each ply at each Gauss point over the run
# (/strength/damage_map of <prefix>.h5, src/results/damage_record.f90), one panel
# per ply, the impacted face's ply first; points at 1 and above have failed.
#
#   gnuplot -e "prefix='out/paper/strength/converged_fig10_clamped_nonlinear'" postproc/damage_map.gp
#
# writes <prefix>_damage.png (or the file `out`). Options (-e): python
# (default /usr/bin/python3, which needs h5py), cols (panels per row,
# default 5), peak=1 for the indices at the largest contact force instead
# of over the run, out (the picture's path).
if (!exists("prefix")) prefix = 'out/impact'
if (!exists("python")) python = '/usr/bin/python3'
if (!exists("cols")) cols = 5
if (!exists("peak")) peak = 0
data = prefix.'_damage.dat'
# The reader, tools/damage-map, is found beside this script: postproc/ and
# tools/ are siblings in the repository and in an installed tree
# (<prefix>/share/impact/{postproc,tools}, make install); when gnuplot does
# not say where the script is (ARG0, gnuplot >= 5.4; none on standard
# input), tools/damage-map of the current directory. Option (-e): damage_map,
# the reader's path.
lastslash(s, i) = i < 1 ? 0 : (s[i:i] eq '/' ? i : lastslash(s, i - 1))
script_dir(s) = lastslash(s, strlen(s)) > 1 ? s[1:lastslash(s, strlen(s)) - 1] : (lastslash(s, strlen(s)) == 1 ? '/' : '.')
if (!exists("damage_map")) damage_map = (exists("ARG0") && strlen(ARG0) > 0) ? script_dir(ARG0).'/../tools/damage-map' : 'tools/damage-map'
system(python." '".damage_map."' '".prefix.".h5'".(peak ? ' --peak' : '')." > '".data."'")
nply = int(system("grep -c '^# ply ' ".data))
fimax = real(system("awk '/largest index/ {print $4}' ".data))
angles = system("awk '/^# ply / {gsub(/[()]/, \"\"); print $4}' ".data)
rows = int(ceil(real(nply)/cols))
set terminal pngcairo size 300*cols, 260*rows + 60 font ",9"
if (!exists("out")) out = prefix.(peak ? '_damage_peak.png' : '_damage.png')
set output out
set multiplot layout rows, cols title sprintf("%s: %s (largest %.3g; 1 = failure)", prefix, \
    peak ? "failure index at the peak force" : "largest failure index over the run", fimax) noenhanced
set size ratio -1
set palette defined (0 "white", 0.5 "yellow", 1 "red", 2 "black")
set cbrange [0:2]
set cbtics ("0" 0, "0.5" 0.5, "1" 1, ">= 2" 2)
unset key
set xlabel "x (mm)"
set ylabel "y (mm)"
do for [k=1:nply] {
    set title sprintf("ply %d (%s deg)", k, word(angles, k))
    plot data index (k-1) u 1:2:3 w p pt 5 ps 0.8 lc palette
}
unset multiplot
print 'written: '.out
