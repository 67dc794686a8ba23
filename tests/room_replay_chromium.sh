#!/bin/sh
# A room run's replay.html in a real browser: the one replay page (replay_chromium.sh tries it
# on a maze run) in metres. The wavefront run in the IR room writes it; headless Chromium loads
# it from the file; the test fails on a JavaScript error (data-js-error on <body>), on a script
# that did not finish (data-replay-ready), on a page that loads anything from elsewhere, on a
# DOM without the slider or the summary's ending, on a boundary not drawn as a wall band, on a
# page that does not open at step 0, on a
# last frame that is not the run's last step, on the step and zoom controls not moving the view
# (clicked through #do=, pressed through #key=), on a status line or key help cut in a
# 1024 x 768 or a 1920 x 1080 window, and on a blank screenshot (png_spread).
# Skips (exit 77) without chromium, unless MAZE_MAPPER_REQUIRE_CHROMIUM is set (chromium_page.sh).
# SCREENSHOT_DIR, when set, receives the screenshots (room-1024x768.png, room-1920x1080.png).
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
load_page "file://$page" "at the start"
grep -q '<dd id="summary-end">goal reached (' "$dir/dom.html" || fail "no summary ending"
grep -q "step 0/$steps  t 0.0 s " "$dir/dom.html" || fail "the page does not open at step 0"
grep -q '<dd id="now-position">' "$dir/dom.html" || fail "no position in metres in the panel"
body=$(grep -o '<body[^>]*>' "$dir/dom.html")
echo "$body" | grep -q 'data-boundary-band="[1-9]' || fail "the room's boundary is not drawn as a wall band: $body"
grep -q '<li id="legend-boundary">' "$dir/dom.html" || fail "no boundary wall in the legend"

load_page "file://$page#frame=99999" "at the last frame"
grep -q "step $steps/$steps  t " "$dir/dom.html" || fail "the last frame is not step $steps"

load_page "file://$page#frame=10&do=next,next,prev,zoom-in,zoom-in&key=ArrowRight,+" "stepped and zoomed"
body=$(grep -o '<body[^>]*>' "$dir/dom.html")
echo "$body" | grep -q 'data-frame="12"' || fail "10, next, next, prev, right arrow is not frame 12: $body"
echo "$body" | grep -q 'data-zoom="3.375"' || fail "three zooms in (1.5 each) are not 3.375 x the whole map: $body"
grep -q "step 12/$steps " "$dir/dom.html" || fail "frame 12 is not step 12"

# The screenshots half way (at the start the map is all never observed).
fits_window 1024x768 room frame=800
fits_window 1920x1080 room frame=800
echo "room replay.html in chromium: ok ($steps steps)"
