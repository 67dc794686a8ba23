#!/bin/sh
# The animation in a real terminal: runs `maze_mapper run --animate` in a tmux pane, waits for
# it to end, captures the pane and checks that the screen shows the final map and summary
# (the alternate screen left, so the normal screen is back). Then a slow run is stopped with
# Ctrl-C: the summary says so and the exit status is 130.
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

tm new-session -d -s mm -x 100 -y 40 \
  "$program run $world --animate --fps 1000 --speed 1000; echo EXIT=\$?; sleep 60"
wait_for "EXIT=" 60
grep -q "EXIT=0" "$pane" || fail "exit status is not 0"
grep -q "^wall_accuracy: 100.00%" "$pane" || fail "no summary"
grep -q "^WWWWWWWWWWWW$" "$pane" || fail "no map"
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
echo "animation in tmux: ok"
