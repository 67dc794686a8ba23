#!/bin/sh
# The animation in a real terminal: runs `maze_mapper run --animate` in a tmux pane, waits for
# it to end, captures the pane and checks that the screen shows the final map and summary
# (the alternate screen left, so the normal screen is back). Then a slow run is stopped with
# Ctrl-C: the summary says so and the exit status is 130. Then the map's width in a terminal:
# two columns a sub-cell by default, one with --narrow, a note when it is too wide even so.
# Usage: animate_tmux.sh MAZE_MAPPER WORLD
set -eu
program=$1
world=$2
socket="maze_mapper_test_$$"
tm() { tmux -L "$socket" "$@"; }
cleanup() { tm kill-server 2>/dev/null || true; }
trap cleanup EXIT

fail() {
  echo "FAIL: $1" >&2
  echo "--- pane ---" >&2
  cat "$pane" >&2
  exit 1
}
pane=$(mktemp)

# wait_for TEXT SECONDS: captures the pane into $pane until it holds TEXT.
wait_for() {
  i=0
  while [ "$i" -lt "$(($2 * 10))" ]; do
    tm capture-pane -p -t mm > "$pane"
    if grep -q "$1" "$pane"; then return 0; fi
    sleep 0.1
    i=$((i + 1))
  done
  fail "no '$1' on the screen after $2 s"
}

# A session that keeps the server up between the tests' sessions (killing the last session
# ends the server, and a new session at that moment finds it gone).
tm new-session -d -s keep "sleep 600"
tm new-session -d -s mm -x 100 -y 40 \
  "$program run $world --animate --fps 1000 --speed 1000; echo EXIT=\$?; sleep 60"
wait_for "EXIT=" 60
grep -q "EXIT=0" "$pane" || fail "exit status is not 0"
grep -q "^wall_accuracy: 100.00%" "$pane" || fail "no summary"
# In a terminal a sub-cell is two columns (the true aspect): lab4x4's north wall is 24 W.
grep -q "^WWWWWWWWWWWWWWWWWWWWWWWW$" "$pane" || fail "no map two columns a sub-cell"
grep -q "^end: done" "$pane" || fail "the run did not end as done"
if grep -q "step .* t .* s" "$pane"; then fail "an animation frame left on the normal screen"; fi
tm kill-session -t mm

# A frame while it runs, then Ctrl-C.
tm new-session -d -s mm -x 100 -y 40 \
  "$program run $world --animate --fps 30 --speed 2; echo EXIT=\$?; sleep 60"
wait_for "visited 2/16" 30
grep -q "@" "$pane" || fail "the robot is not drawn"
tm send-keys -t mm C-c
wait_for "EXIT=" 30
grep -q "EXIT=130" "$pane" || fail "exit status after Ctrl-C is not 130"
grep -q "^end: stopped (interrupted by Ctrl-C)" "$pane" || fail "no summary after Ctrl-C"
tm kill-session -t mm

# --narrow: the classroom look in a terminal too.
tm new-session -d -s mm -x 100 -y 40 "$program run $world --narrow --quiet; echo EXIT=\$?; sleep 60"
wait_for "EXIT=" 60
grep -q "^WWWWWWWWWWWW$" "$pane" || fail "--narrow: no map one column a sub-cell"
tm kill-session -t mm

# A map too wide for the terminal even one column a sub-cell (K 9: 36 columns in 30): a note
# on how to see it whole.
tm new-session -d -s mm -x 30 -y 100 "$program run $world --subcells 9 --max-steps 1 --quiet; echo EXIT=\$?; sleep 60"
wait_for "EXIT=" 60
grep -q "^note: the map is 36 columns" "$pane" || fail "no note on a map wider than the terminal"
tm kill-session -t mm
# A --speed faster than the terminal can draw: frames are skipped, the run keeps its speed (a
# 128 x 128 maze, about 33,000 moves, took over ten minutes when every move was a frame).
big=$(mktemp --suffix=.txt)
"$program" generate 128x128 -o "$big"
start=$(date +%s)
tm new-session -d -s mm -x 100 -y 40 "$program run $big --animate --speed 1000000 --fps 30; echo EXIT=\$?; sleep 60"
wait_for "EXIT=" 60
grep -q "EXIT=0" "$pane" || fail "--speed 1000000 on 128x128: exit status is not 0"
grep -q "^end: done" "$pane" || fail "--speed 1000000 on 128x128: the run did not end as done"
echo "--animate --speed 1000000 --fps 30 on 128x128: $(($(date +%s) - start)) s"
rm -f "$big"
tm kill-session -t mm

echo "animation and map widths in tmux: ok"
