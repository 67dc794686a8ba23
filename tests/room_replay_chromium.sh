#!/bin/sh
# A room run's replay.html in a real browser (as replay_chromium.sh for the maze runs' page):
# the wavefront run in the IR room writes it; headless Chromium loads it from the file; the test
# fails on a JavaScript error (data-js-error on <body>), on a script that did not finish
# (data-replay-ready), on a page that loads anything from elsewhere, on a DOM without the
# slider or the summary's ending, on a last frame that is not the run's last step, on #frame=0
# not showing step 1, and on a blank screenshot (png_spread).
# Skips (exit 77) without chromium, unless MAZE_MAPPER_REQUIRE_CHROMIUM is set (chromium_page.sh).
# Usage: room_replay_chromium.sh MAZE_MAPPER PNG_SPREAD WORLDS_DIR
set -eu
program=$1
png_spread=$2
worlds=$3
. "$(dirname "$0")/chromium_page.sh"

"$program" room "$worlds/ir_room.room" --strategy wavefront --model pie --robot ir-fan --goal 4.7,2.7 --quiet \
  -o "$dir/out" > "$dir/run.out" || fail "the run failed"
page="$dir/out/replay.html"
self_contained "$page"
steps=$(sed -n 's/^steps: *//p' "$dir/run.out")
load_page "file://$page" "at the end"
grep -q '<dd id="summary-end">goal reached (' "$dir/dom.html" || fail "no summary ending"
grep -q "step $steps  t " "$dir/dom.html" || fail "the last frame is not step $steps"

load_page "file://$page#frame=0" "at #frame=0"
grep -q 'step 1  t ' "$dir/dom.html" || fail "#frame=0 does not show step 1"

browser --window-size=1100,800 --hide-scrollbars --screenshot="$dir/shot.png" "file://$page" > /dev/null ||
  fail "chromium --screenshot failed"
"$png_spread" "$dir/shot.png" || fail "blank screenshot"
echo "room replay.html in chromium: ok ($steps steps)"
