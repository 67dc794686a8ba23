#!/bin/sh
# The Python runner's replay.html of an arena run in a real browser: the one replay page in
# metres (room_replay_chromium.sh tries a room run's). A controller that keeps a metric map
# (maze_mapper.keep_map) and updates it in place drives in thick_arena; headless Chromium loads
# the page from the file; the test fails on a JavaScript error, a script that did not finish, a
# page that loads anything from elsewhere, a boundary not drawn as a wall band, a page that does
# not open at the first step or whose last frame is not the run's last step, a status line cut
# in a 1024 x 768 window, and a blank screenshot. Then the same without a kept map (the path
# only). Skips (exit 77) without chromium, unless MAZE_MAPPER_REQUIRE_CHROMIUM is set.
# Usage: kept_map_replay_chromium.sh PYTHON PNG_SPREAD WORLDS_DIR   (PYTHONPATH on the module)
set -eu
python=$1
png_spread=$2
worlds=$3
. "$(dirname "$0")/../../tests/chromium_page.sh"

cat > "$dir/mapper.py" <<'PY'
from controller import Robot
import math
import numpy as np
import maze_mapper
grid = np.zeros((34, 34))
maze_mapper.keep_map(grid, origin=(-8.5, -8.5), cell_size_m=0.5)
robot = Robot()
left, right = robot.getDevice('left motor'), robot.getDevice('right motor')
for m in (left, right):
    m.setPosition(math.inf)
    m.setVelocity(5.0)
for k in range(60):
    robot.step(32)
    grid[0, :] += 0.41
    grid[2:5, 2:5] -= 0.85
    grid[k % 34, 20] = 2.0
PY
sed -e '/keep_map/d' -e '/grid/d' "$dir/mapper.py" > "$dir/driver.py"

for controller in mapper driver; do
  "$python" -m maze_mapper.run "$dir/$controller.py" --world "$worlds/thick_arena.xml" --out "$dir/$controller" \
    > "$dir/run.out" 2> "$dir/run.err" || fail "the $controller run failed: $(cat "$dir/run.err")"
  page="$dir/$controller/replay.html"
  self_contained "$page"
  load_page "file://$page" "at the start ($controller)"
  grep -q "step 1/60  t 0.0 s " "$dir/dom.html" || fail "the $controller page does not open at step 1"
  grep -q '<dd id="now-position">' "$dir/dom.html" || fail "no position in metres in the panel ($controller)"
  grep -o '<body[^>]*>' "$dir/dom.html" | grep -q 'data-boundary-band="[1-9]' ||
    fail "the arena's boundary is not drawn as a wall band ($controller)"
  load_page "file://$page#frame=99999" "at the last frame ($controller)"
  grep -q "step 60/60  t " "$dir/dom.html" || fail "the last frame of the $controller page is not step 60"
  fits_window 1024x768 "arena-$controller" frame=30
done
echo "arena replay.html in chromium: ok (with a kept map and without)"
