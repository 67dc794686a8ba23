#!/bin/sh
# The example mms algorithms (examples/mms/: floodfill in Python and in C++) on every
# shipped maze (not the arenas) and on generated classic 16 x 16 mazes, in both wall modes: each run must end
# with the algorithm's own exit and the robot in the centre (maze_mapper mms exit status 0).
# Usage: mms_examples.sh MAZE_MAPPER CPP_FLOODFILL SOURCE_DIR [GENERATED_COUNT]
set -eu
program=$1
cpp_floodfill=$2
source_dir=$3
generated=${4:-30}
python_floodfill="python3 $source_dir/examples/mms/floodfill.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

check() {  # world walls algorithm...
  world=$1 walls=$2
  shift 2
  if ! "$program" mms "$world" --quiet --walls "$walls" --wall-limit 120 -- "$@" > "$work/out" 2>&1; then
    echo "FAILED: $world --walls $walls -- $*"
    grep -E '^(end|goal|score):' "$work/out" || tail -5 "$work/out"
    failures=$((failures + 1))
  fi
}

for world in "$source_dir"/worlds/*.txt "$source_dir"/worlds/*.num "$source_dir"/worlds/*.xml; do
  # The mazes only: `show` prints a maze as a text map (posts first), an arena (a room of
  # obstacles, which an mms algorithm cannot drive cell by cell) as a header and a drawing.
  case $("$program" show "$world" | head -n 1) in
    o*|+*) ;;
    *) continue ;;
  esac
  for walls in truth sensed; do
    check "$world" "$walls" $python_floodfill
    check "$world" "$walls" "$cpp_floodfill"
  done
done
echo "shipped mazes: done"

mkdir "$work/generated"
seed=1
while [ "$seed" -le "$generated" ]; do
  "$program" generate 16x16 --seed "$seed" -o "$work/generated/classic$seed.txt"
  seed=$((seed + 1))
done
for walls in truth sensed; do
  for algorithm in python cpp; do
    if [ "$algorithm" = python ]; then set -- $python_floodfill; else set -- "$cpp_floodfill"; fi
    if ! "$program" batch "$work/generated" --jobs 2 --walls "$walls" --wall-limit 120 -- "$@" > "$work/batch" 2>&1; then
      echo "FAILED: batch of $generated generated mazes, --walls $walls, $algorithm"
      cat "$work/batch"
      failures=$((failures + 1))
    fi
  done
done
echo "generated mazes: done"
[ "$failures" -eq 0 ] && echo "every run reached the centre"
exit "$failures"
