# damage_map.gp: the damage map of a run with &strength, ply by ply: the
# largest failure index of each ply at each Gauss point over the run
# (/strength/damage_map of <prefix>.h5, src/results/damage_record.f90), one panel
# per ply, the impacted face's ply first; points at 1 and above have failed.
# The title names the scene (postproc/scene.gp: the deck echo of
# <prefix>_history.dat), the criterion, the largest index and its mode, and
# where damage started (<prefix>_summary.dat); each panel the ply's largest
# index and its mode; a blue cross marks the impact point (&impactor x0, y0).
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
# the reader's path. postproc/scene.gp is found the same way.
lastslash(s, i) = i < 1 ? 0 : (s[i:i] eq '/' ? i : lastslash(s, i - 1))
script_dir(s) = lastslash(s, strlen(s)) > 1 ? s[1:lastslash(s, strlen(s)) - 1] : (lastslash(s, strlen(s)) == 1 ? '/' : '.')
postproc = (exists("ARG0") && strlen(ARG0) > 0) ? script_dir(ARG0) : 'postproc'
if (!exists("damage_map")) damage_map = (exists("ARG0") && strlen(ARG0) > 0) ? script_dir(ARG0).'/../tools/damage-map' : 'tools/damage-map'
system(python." '".damage_map."' '".prefix.".h5'".(peak ? ' --peak' : '')." > '".data."'")
nply = int(system("grep -c '^# ply ' ".data))
fimax = real(system("awk '/largest index/ {print $4}' ".data))
angles = system("awk '/^# ply / {gsub(/[()]/, \"\"); print $4}' ".data)
criterion = system("awk '/criterion/ {sub(/.*criterion /, \"\"); sub(/;.*/, \"\"); print; exit}' ".data)
criterion_name = criterion eq 'hashin' ? "Hashin's criterion (1980)" : \
    (criterion eq 'max_stress' ? 'the maximum stress criterion' : \
    (criterion eq 'tsai_wu' ? 'the Tsai–Wu criterion (1971)' : 'criterion '.criterion))
# the modes' words, by code + 1 (src/strength/failure_criteria.f90)
mode_name(m) = m == 1 ? 'fibre tension' : m == 2 ? 'fibre compression' : m == 3 ? 'matrix tension' : \
    m == 4 ? 'matrix compression' : m == 5 ? 'shear 12/13' : m == 6 ? 'shear 23' : m == 0 ? 'none' : '?'
summary_value(key) = system(sprintf("awk -F' = ' '$1 == \"%s\" {gsub(/_/, \" \", $2); print $2}' '%s_summary.dat' 2>/dev/null", key, prefix))
onset = summary_value('failure_onset_us')
onset_text = strlen(onset) == 0 ? '' : (onset eq 'none' ? 'no index reached 1' : \
    sprintf("damage starts at %.0f µs in ply %s (%s)", real(onset), summary_value('failure_ply'), summary_value('failure_mode')))
set encoding utf8
file = prefix.'_history.dat'
load postproc.'/scene.gp'
x0 = 1e3*real(deck_value('x0'))
y0 = 1e3*real(deck_value('y0'))
# the largest index of each ply and its mode
array ply_max[nply]
array ply_mode[nply]
do for [k=1:nply] {
    stats data index (k-1) using 3 nooutput
    ply_max[k] = STATS_max
    i = int(STATS_index_max)
    stats data index (k-1) every ::i::i using 4 nooutput
    ply_mode[k] = STATS_max
}
k_top = 1
do for [k=1:nply] { if (ply_max[k] > ply_max[k_top]) { k_top = k } }
rows = int(ceil(real(nply)/cols))
set terminal pngcairo size 300*cols, 230*rows + 110 font ",9"
if (!exists("out")) out = prefix.(peak ? '_damage_peak.png' : '_damage.png')
set output out
set multiplot layout rows, cols title sprintf("%s\n%s, %s: largest %.3g (ply %d, %s); 1 = failure%s\n%s", scene, \
    peak ? "failure index at the peak force" : "damage map, the largest failure index over the run", \
    criterion_name, fimax, k_top, mode_name(ply_mode[k_top]), \
    peak ? '' : '; mode: that of the ply''s largest index', \
    (strlen(onset_text) > 0 ? onset_text.'; ' : '').'blue cross: the impact point') font ",11" noenhanced
set size ratio -1
set palette defined (0 "white", 0.5 "yellow", 1 "red", 2 "black")
set cbrange [0:2]
set cbtics ("0" 0, "0.5" 0.5, "1" 1, "≥ 2" 2)
unset key
set xlabel "x (mm)"
set ylabel "y (mm)"
set label 1 "" at x0, y0 point pt 1 ps 2.5 lw 2 lc rgb "blue" front
do for [k=1:nply] {
    set title sprintf("ply %d (%s°): %.3g%s", k, word(angles, k), ply_max[k], \
        peak ? '' : ', '.mode_name(ply_mode[k])) noenhanced
    plot data index (k-1) u 1:2:3 w p pt 5 ps 0.8 lc palette
}
unset multiplot
print 'written: '.out
