#!/bin/sh
# Builds the fuzz preset and runs each libFuzzer target for N seconds (default 60) from the
# committed seed corpus (fuzz/corpus/<target>/, read-only: new inputs go to a scratch
# directory). Fails on the first crash, hang, leak or sanitizer report; the input that did
# it is left in build/fuzz/artifacts/.
#   usage: fuzz/run_short.sh [SECONDS]
set -eu
seconds=${1:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz --target fuzz_text_map fuzz_num fuzz_xml fuzz_run_cli
artifacts="$root/build/fuzz/artifacts"
mkdir -p "$artifacts"
for name in text_map num xml run_cli; do
  scratch=$(mktemp -d)
  echo "fuzz_$name: ${seconds} s"
  if ! "$root/build/fuzz/bin/fuzz_$name" "$scratch" "$root/fuzz/corpus/$name" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
      -artifact_prefix="$artifacts/fuzz_$name-" -print_final_stats=1 2>"$artifacts/fuzz_$name.log"; then
    tail -n 40 "$artifacts/fuzz_$name.log" >&2
    rm -rf "$scratch"
    echo "fuzz_$name: FAILED (input in $artifacts)" >&2
    exit 1
  fi
  grep -E '^stat::number_of_executed_units' "$artifacts/fuzz_$name.log" || true
  rm -rf "$scratch"
done
echo "all fuzz targets ran ${seconds} s without a failure"
