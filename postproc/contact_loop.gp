# contact_loop.gp: the contact force against the indentation from an impact
# history file, the cycle of the indentation law (the paper's Fig. 1, eq.
# 11-13): loading F = k alpha^1.5, unloading from (alpha_m, F_m) towards the
# permanent indentation alpha_0 (and back up the same curve while the
# impactor stays in contact), reloading after a separation back to
# (alpha_m, F_m) (src/model/contact_law.f90); each step coloured by its
# branch (history column 14), the law's loading curve dashed.
#
#   gnuplot -e "prefix='out/clamped'" postproc/contact_loop.gp
#
# writes <prefix>_contact_loop.png (or the file `out`). Columns: 2 force_N,
# 3 indentation_mm, 14 branch (0 no contact, 1 loading, 2 unloading,
# 3 reloading). k comes from the deck echo at the top of the history file,
# the permanent indentation from <prefix>_summary.dat; the title names the
# scene (postproc/scene.gp, beside this script).
if (!exists("prefix")) prefix = 'out/clamped'
file = prefix.'_history.dat'
lastslash(s, i) = i < 1 ? 0 : (s[i:i] eq '/' ? i : lastslash(s, i - 1))
script_dir(s) = lastslash(s, strlen(s)) > 1 ? s[1:lastslash(s, strlen(s)) - 1] : (lastslash(s, strlen(s)) == 1 ? '/' : '.')
postproc = (exists("ARG0") && strlen(ARG0) > 0) ? script_dir(ARG0) : 'postproc'
set encoding utf8
load postproc.'/scene.gp'
k_law = real(deck_value('k'))                       # N/m^1.5
alpha_0 = real(system("awk -F' = ' '$1 == \"permanent_indentation_mm\" {print $2 + 0}' '".prefix."_summary.dat' 2>/dev/null"))
stats file using 3 nooutput
alpha_top = STATS_max
if (!exists("out")) out = prefix.'_contact_loop.png'
set terminal pngcairo size 900,700 font ",11"
set output out
set title scene."\ncontact force against indentation α: the indentation law's cycle (eq. 11–13)" noenhanced
set xlabel "indentation α = w_{impactor} − w_{plate} (mm)"
set ylabel "contact force F (N)"
set grid
set key top left
set xrange [0:*]
set yrange [0:*]
set samples 300
branch(b, y) = (column(14) == b) ? y : NaN
if (alpha_0 > 0) set arrow 1 from alpha_0, graph 0 to alpha_0, graph 1 nohead dt 3 lc rgb "gray40"
if (alpha_0 > 0) set label 1 sprintf(" α_0 = %.3g mm, the permanent indentation", alpha_0) at alpha_0, graph 0.55 left tc rgb "gray40"
plot [0:alpha_top*1.05] \
     k_law > 0 ? k_law*(x*1e-3)**1.5 : NaN with lines lw 1.5 dt 2 lc rgb "black" title "loading law F = k α^{1.5}", \
     file using 3:2 with lines lw 0.8 lc rgb "gray60" title "the run, step by step", \
     file using 3:(branch(1, $2)) with points pt 7 ps 0.45 lc rgb "#d62728" title "loading", \
     file using 3:(branch(2, $2)) with points pt 7 ps 0.45 lc rgb "#1f77b4" title "unloading branch (also back up it while in contact)", \
     file using 3:(branch(3, $2)) with points pt 7 ps 0.45 lc rgb "#2ca02c" title "reloading, after a separation"
print 'written: '.out
