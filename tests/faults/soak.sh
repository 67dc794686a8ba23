#!/bin/sh
# The soak: `run --out` on random generated mazes (8x8 to 31x31, 0 to 3 snapshots), each
# interrupted by SIGINT, SIGTERM or SIGHUP 0 to 599 ms in, all drawn from SEED. After each
# run: the exit status is 128 + the signal (or 0 or 1 when the run ended first), every output
# present is whole (a CSV, JSON or YAML ends with a newline, a PNG with its IEND chunk), and no
# temporary (.NAME.tmp.PID) is left. One line a fault, then one line of figures; exit 1 on
# any fault. The fault suite (run_faults.sh) runs 8; a long run, outside CI:
#   usage: soak.sh PROGRAM RUNS [SEED] [DIR]     (DIR: a scratch folder, default a new one)
set -u
program=$1
runs=$2
seed=${3:-1}
dir=${4:-}
if [ -z "$dir" ]; then
  dir=$(mktemp -d)
  trap 'rm -rf "$dir"' EXIT
fi
mkdir -p "$dir"
interrupted=0
finished=0
left=0
cut=0
odd=0

fault() {
  printf 'soak run %s (%sx%s, SIG%s after %s ms): %s\n' "$i" "$size" "$size" "$sig" "$delay_ms" "$1"
}
. "$(dirname "$0")/whole_outputs.sh"  # check_outputs

i=0
while [ "$i" -lt "$runs" ]; do
  i=$((i + 1))
  seed=$(((seed * 1103515245 + 12345) % 2147483648))
  size=$((8 + seed % 24))
  delay_ms=$(((seed / 64) % 600))
  case $(((seed / 8) % 3)) in 0) sig=INT want=130 ;; 1) sig=TERM want=143 ;; *) sig=HUP want=129 ;; esac
  snapshots=$(((seed / 16) % 4))
  "$program" generate "${size}x${size}" --seed "$seed" -o "$dir/maze.txt" || fault "generate failed"
  if [ "$snapshots" -gt 0 ]; then extra="--snapshots $snapshots"; else extra=""; fi
  # shellcheck disable=SC2086
  "$program" run "$dir/maze.txt" --out "$dir/out" $extra >/dev/null 2>"$dir/err" &
  pid=$!
  sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
  kill -"$sig" "$pid" 2>/dev/null
  status=0
  wait "$pid" || status=$?
  case $status in
    "$want") interrupted=$((interrupted + 1)) ;;
    0 | 1) finished=$((finished + 1)) ;;
    *) odd=$((odd + 1)); fault "exit $status" ;;
  esac
  check_outputs "$dir/out"
done
echo "soak: $runs runs (seed ${3:-1}): $interrupted interrupted, $finished ended first, $odd other exits; $left temporaries left, $cut outputs cut"
[ "$((left + cut + odd))" -eq 0 ]
