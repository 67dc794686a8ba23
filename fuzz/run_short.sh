#!/bin/sh
# Builds the fuzz preset's nine targets and runs each libFuzzer target for N seconds
# (default 60) from the committed seed corpus (fuzz/corpus/<target>/, read-only: new inputs
# go to a scratch directory), JOBS targets at a time (default 1). Fails when any target
# reports a crash, hang, leak or sanitizer error; the input that did it is left in
# build/fuzz/artifacts/ and the end of that target's log is printed.
#   usage: fuzz/run_short.sh [SECONDS] [JOBS]
set -eu
seconds=${1:-60}
jobs=${2:-1}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
cmake --preset fuzz >/dev/null
targets="text_map num xml room robot_json mms_protocol run_cli format batch_csv"
# shellcheck disable=SC2046 # one word a target
cmake --build --preset fuzz --target $(for t in $targets; do printf 'fuzz_%s ' "$t"; done)
artifacts="$root/build/fuzz/artifacts"
mkdir -p "$artifacts"
# fontconfig's process-lifetime caches are no leak of ours (tests/lsan.supp, as the presets).
export LSAN_OPTIONS="suppressions=$root/tests/lsan.supp:print_suppressions=0"

# Runs one target; its exit status is libFuzzer's (0: no report in the time given).
run_one() {
  name=$1
  scratch=$(mktemp -d)
  status=0
  "$root/build/fuzz/bin/fuzz_$name" "$scratch" "$root/fuzz/corpus/$name" \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -artifact_prefix="$artifacts/fuzz_$name-" -print_final_stats=1 \
    >"$artifacts/fuzz_$name.out" 2>"$artifacts/fuzz_$name.log" || status=$?
  rm -rf "$scratch"
  return "$status"
}

# Reports one finished target; returns 1 when it failed.
report() {
  name=$1
  status=$2
  if [ "$status" -ne 0 ]; then
    tail -n 40 "$artifacts/fuzz_$name.log" >&2
    echo "fuzz_$name: FAILED with status $status (input in $artifacts)" >&2
    return 1
  fi
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$artifacts/fuzz_$name.log")
  echo "fuzz_$name: ${seconds} s, ${executions:-?} executions, no report"
}

failed=0
# shellcheck disable=SC2086
set -- $targets
while [ $# -gt 0 ]; do
  batch=""
  pids=""
  n=0
  while [ $# -gt 0 ] && [ "$n" -lt "$jobs" ]; do
    echo "fuzz_$1: running ${seconds} s"
    run_one "$1" &
    batch="$batch $1"
    pids="$pids $!"
    n=$((n + 1))
    shift
  done
  for name in $batch; do
    pids=${pids# }
    pid=${pids%% *}
    pids=${pids#"$pid"}
    status=0
    wait "$pid" || status=$?
    report "$name" "$status" || failed=1
  done
done
if [ "$failed" -ne 0 ]; then
  exit 1
fi
echo "all fuzz targets ran ${seconds} s without a report"
