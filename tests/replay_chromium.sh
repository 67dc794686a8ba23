#!/bin/sh
# replay.html in a real browser: a run writes it, headless Chromium (no sandbox: CI runs as
# root; a virtual time budget for the page's script) loads it from the file, and the test
# fails on a JavaScript error (the page's window.onerror writes data-js-error on <body>), on
# a script that did not finish (data-replay-ready on <body> is set after the last frame is
# drawn), on a DOM without the slider, the K x K matrix or the summary, on a page that does
# not open at the start, on a maze's page with a boundary band or without room for landmarks
# on its corners, on a page that loads anything from elsewhere, on a status line or key
# help cut in a 1024 x 768 or a 1920 x 1080 window, and on a blank screenshot (png_spread).
# #frame=N then #frame=0 seeks on and back (the path that redraws from nothing). A run with
# --localize shows its belief in the panel.
# Skips (exit 77) when chromium is not installed, unless MAZE_MAPPER_REQUIRE_CHROMIUM is set
# (.ci/run sets it): then a missing chromium fails.
# SCREENSHOT_DIR, when set, receives the screenshots (maze-1024x768.png, maze-1920x1080.png).
# Usage: replay_chromium.sh MAZE_MAPPER PNG_SPREAD WORLD
set -eu
program=$1
png_spread=$2
world=$3

. "$(dirname "$0")/chromium_page.sh"

"$program" run "$world" --quiet --no-trace --out "$dir/out" > "$dir/run.out" || fail "the run failed"
page="$dir/out/replay.html"
self_contained "$page"
load_page "file://$page" "at the start"
grep -q '<button id="play"' "$dir/dom.html" || fail "no play button"
coverage=$(sed -n 's/^coverage: //p' "$dir/run.out")
grep -q "<dd id=\"summary-coverage\">$coverage</dd>" "$dir/dom.html" || fail "no summary coverage $coverage"
grep -q '<dd id="summary-wall_accuracy">' "$dir/dom.html" || fail "no summary wall_accuracy"
grep -q '<td class="occupied">+' "$dir/dom.html" || fail "no K x K matrix with an occupied sub-cell"
moves=$(sed -n 's/^moves: //p' "$dir/run.out")
grep -q "move 0/$moves " "$dir/dom.html" || fail "the page does not open at move 0/$moves"

load_page "file://$page#frame=$moves" "at #frame=$moves"
grep -q "move $moves/$moves " "$dir/dom.html" || fail "#frame=$moves does not show move $moves/$moves"
load_page "file://$page#frame=$moves&key=Home" "at #frame=$moves, then Home"
grep -q "move 0/$moves " "$dir/dom.html" || fail "Home from the end does not show move 0/$moves"

echo "$(grep -o '<body[^>]*>' "$dir/dom.html")" | grep -q 'data-boundary-band="0"' || fail "a maze's page draws a boundary band"
# Landmarks on a maze's corners (the course's localization worlds): the view holds them whole.
"$program" run "$(dirname "$0")/data/worlds/course_arena5_starts.xml" --quiet --no-trace --out "$dir/corners" \
  > "$dir/corners.out" || fail "the run with corner landmarks failed"
load_page "file://$dir/corners/replay.html" "with landmarks on the maze's corners"
margin=$(grep -o '<body[^>]*>' "$dir/dom.html" | sed -n 's/.*data-margin="\([0-9]*\)".*/\1/p')
[ "${margin:-0}" -gt 0 ] || fail "no margin round the maze for its corner landmarks (data-margin '$margin')"
fits_window 1024x768 maze
fits_window 1920x1080 maze
# A 64 x 64 run in a 1280 x 900 window: the map fills the stage, the controls step and zoom
# (clicked through #do=, pressed through #key=), and the panel shows the run at that move.
"$program" generate 64x64 -o "$dir/m64.txt"
"$program" run "$dir/m64.txt" --quiet --no-trace --out "$dir/big" > "$dir/big.out" 2> /dev/null || fail "the 64x64 run failed"
big_moves=$(sed -n 's/^moves: //p' "$dir/big.out")
browser --window-size=1280,900 --dump-dom "file://$dir/big/replay.html#frame=680&do=next,next,prev,zoom-in,zoom-in&key=ArrowRight,+" \
  > "$dir/dom.html" || fail "chromium --dump-dom of the 64x64 replay failed"
grep -q 'data-js-error' "$dir/dom.html" && fail "a JavaScript error in the 64x64 replay"
body=$(grep -o '<body[^>]*>' "$dir/dom.html")
view_w=$(echo "$body" | sed -n 's/.*data-view-width="\([0-9]*\)".*/\1/p')
view_h=$(echo "$body" | sed -n 's/.*data-view-height="\([0-9]*\)".*/\1/p')
[ "${view_w:-0}" -ge 800 ] && [ "${view_h:-0}" -ge 600 ] || fail "the map's stage is ${view_w}x${view_h} in a 1280x900 window"
echo "$body" | grep -q 'data-frame="682"' || fail "680, next, next, prev, right arrow is not frame 682: $body"
echo "$body" | grep -q 'data-zoom="3.375"' || fail "three zooms in (1.5 each) are not 3.375 x the whole map: $body"
grep -q "<dd id=\"now-move\">682 of $big_moves</dd>" "$dir/dom.html" || fail "the panel does not show move 682 of $big_moves"
now_coverage=$(sed -n 's/.*<dd id="now-coverage">\([0-9.]*\)%.*/\1/p' "$dir/dom.html")
awk -v c="$now_coverage" 'BEGIN { exit !(c > 0 && c < 100) }' || fail "coverage at move 682 is '$now_coverage', not part of the run's"
grep -q '<dd id="now-visited">[1-9][0-9]* of 4096 cells</dd>' "$dir/dom.html" || fail "no cells visited at move 682"
echo "64x64 replay at 1280x900: stage ${view_w}x${view_h}, move 682 of $big_moves, coverage $now_coverage%, zoom 3.375"
# run --localize: the panel shows the filter's most likely cell at each frame, as the run
# printed it at that move.
"$program" run "$(dirname "$0")/../worlds/loc5x5.txt" --localize --start 2,2 --no-trace --out "$dir/loc" \
  > "$dir/loc.out" || fail "the run with --localize failed"
printed=$(grep -A 18 '^localize: move 4 ' "$dir/loc.out" | sed -n 's/^most likely: \(cell [0-9]* ([0-9.]*)\)$/\1/p')
[ -n "$printed" ] || fail "the run with --localize printed no belief at move 4"
load_page "file://$dir/loc/replay.html#frame=4" "with --localize at move 4"
grep -q "<dd id=\"now-belief\">$printed</dd>" "$dir/dom.html" || fail "the panel does not show the belief $printed at move 4"
grep -q '<li id="legend-belief">' "$dir/dom.html" || fail "no legend of the belief"
echo "replay.html in chromium: ok"
