#!/bin/sh
# The Python runner's soak: python3 -m maze_mapper.run with a wall follower
# (tests/faults/wall_follower.py) on worlds/maze8x8.txt with --out, SIGTERM sent 100 to 449 ms
# after its start, drawn from SEED, under the load of the runs themselves. After each run:
# the exit status is 143 (or 0 when the run ended first: --max-steps 2000), every output
# present is whole (trace.csv and summary.json end with a newline, trace.csv has one header,
# a PNG ends with its IEND chunk), and no temporary (.NAME.tmp.PID) is left. One line a fault,
# then one line of figures (how many runs a signal stopped at a step, with their summary, and
# how many it ended at once: before the runner took the signals, or while it wrote its files);
# exit 1 on any fault. PYTHONPATH must reach the built module. About 20 s for 40 runs.
#   usage: soak_python.sh PYTHON SOURCE_DIR RUNS [SEED]
set -u
python=$1
source_dir=$2
runs=$3
seed=${4:-1}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
interrupted=0
stopped=0
finished=0
left=0
cut=0
odd=0
started=$(date +%s)

fault() {
  printf 'python soak run %s (SIGTERM after %s ms): %s\n' "$i" "$delay_ms" "$1"
}
. "$source_dir/tests/faults/whole_outputs.sh"  # check_outputs

i=0
while [ "$i" -lt "$runs" ]; do
  i=$((i + 1))
  seed=$(((seed * 1103515245 + 12345) % 2147483648))
  delay_ms=$((100 + (seed / 64) % 350))
  "$python" -m maze_mapper.run "$source_dir/tests/faults/wall_follower.py" --world "$source_dir/worlds/maze8x8.txt" \
    --max-steps 2000 --out "$dir/out" >"$dir/stdout" 2>"$dir/err" &
  pid=$!
  sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
  kill -TERM "$pid" 2>/dev/null
  status=0
  wait "$pid" 2>/dev/null || status=$?  # (no shell's "Terminated" for a run ended at once)
  case $status in
    143)
      interrupted=$((interrupted + 1))
      grep -q '^end: stopped (interrupted by SIGTERM)$' "$dir/stdout" && stopped=$((stopped + 1))
      ;;
    0) finished=$((finished + 1)) ;;
    *) odd=$((odd + 1)); fault "exit $status: $(tail -n 3 "$dir/err")" ;;
  esac
  grep -q Traceback "$dir/err" && { odd=$((odd + 1)); fault "a traceback: $(cat "$dir/err")"; }
  check_outputs "$dir/out"
  if [ -e "$dir/out/trace.csv" ] && [ "$(grep -c '^step,' "$dir/out/trace.csv")" != 1 ]; then
    cut=$((cut + 1))
    fault "trace.csv has $(grep -c '^step,' "$dir/out/trace.csv") headers"
  fi
done
echo "python soak: $runs runs (seed ${4:-1}) in $(($(date +%s) - started)) s: $interrupted interrupted ($stopped at a step, $((interrupted - stopped)) at once), $finished ended first, $odd other exits; $left temporaries left, $cut outputs cut"
[ "$((left + cut + odd))" -eq 0 ]
