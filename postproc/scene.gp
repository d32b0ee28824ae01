# scene.gp: what a run was, from the deck echo at the top of its history
# file, for the titles of history.gp, contact_loop.gp and damage_map.gp
# (which load it from their own directory). Before loading, set `file` to
# the history file (<prefix>_history.dat). It defines
#
#   deck_value(key)  the first word of a deck variable's echoed value ('a'
#                    -> '0.15', 'edges' -> 'clamped', 'angles' -> the
#                    number of plies), '' when the echo has no such line
#   scene            "clamped plate 150 × 100 × 2.7 mm, 20 plies; impactor
#                    243 g at 3 m/s; nonlinear theory", or the file's name
#                    without a deck echo
#
# Needs `set encoding utf8` for the × (the scripts set it). The echo's lines
# are `# &group  name = value unit, name = value unit, ...`, continued on
# lines `#            name = ...` (src/deck/deck_echo.f90).
scene_awk = '/^# columns/ { exit } /^#/ { s = s " " substr($0, 2) } ' . \
    'END { if (!match(s, " " k " = [^=]*")) exit; t = substr(s, RSTART + length(k) + 4, RLENGTH - length(k) - 4); ' . \
    'if (k == "angles") { sub(/[a-z].*/, "", t); print split(t, parts, ","); exit } ' . \
    'gsub(/\047/, "", t); split(t, parts, /[ ,]+/); print parts[1] }'
deck_value(key) = system(sprintf("awk -v k='%s' '%s' '%s' 2>/dev/null", key, scene_awk, file))
scene_edges = deck_value('edges')
if (strlen(scene_edges) > 0 && strlen(deck_value('mass')) > 0) {
    scene_edges = (scene_edges eq 'simply_supported') ? 'simply supported' : scene_edges
    scene = sprintf("%s plate %g × %g × %g mm, %s plies; impactor %g g at %g m/s; %s theory", scene_edges, \
        1e3*real(deck_value('a')), 1e3*real(deck_value('b')), 1e3*real(deck_value('h')), deck_value('angles'), \
        1e3*real(deck_value('mass')), real(deck_value('velocity')), deck_value('theory'))
} else {
    scene = file
}
