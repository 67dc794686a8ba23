#!/bin/sh
# Builds the `bench` preset and prints one table of every benchmark:
# the lidar scan (bench_lidar), the course robot's cost a control step and a lidar beam
# (bench_course_run), ray integration against OctoMap and the default-world scan
# update (bench_ray_integration), `maze_mapper run` on a 16 x 16 maze, and the scaling runs
# (bench/scale.sh). Run from anywhere:
#
#   bench/run_all.sh [SIZE ...]      SIZE: scaling sizes (default 64 256 512 1024)
#
# CPU times are the steadier numbers on a shared machine; wall times include waiting for
# a core. Needs cmake, ninja, libbenchmark-dev; liboctomap-dev for the OctoMap column
# (scripts/install-bench-deps.sh).
set -eu

here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
cmake --preset bench >/dev/null
cmake --build --preset bench >/dev/null
bin=build/bench/bin

echo "# maze_mapper benchmarks"
echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "machine: $(nproc) cores, $(awk -F': ' '/model name/ {print $2; exit}' /proc/cpuinfo), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
echo

echo "## Lidar scan, 360 beams (bench_lidar; Google Benchmark, CPU time)"
"$bin/bench_lidar" --benchmark_min_time=0.2 --benchmark_format=csv 2>/dev/null |
    awk -F, 'NR > 1 { gsub(/"/, "", $1); printf "%-40s %10.2f us cpu %10.2f us real\n", $1, $4, $3 }'
echo

echo "## Lidar scan in a 20 x 20 m arena, 360 beams (bench_arena; Google Benchmark, CPU time)"
"$bin/bench_arena" --benchmark_min_time=0.2 --benchmark_format=csv 2>/dev/null |
    awk -F, 'NR > 1 { gsub(/"/, "", $1); printf "%-52s %10.2f us cpu %10.2f us real\n", $1, $4, $3 }'
echo

echo "## The course robot: ns a control step and a lidar beam in real runs (bench_course_run; thread CPU time)"
"$bin/bench_course_run" --rounds 5 64 256
echo

echo "## Ray integration and scan update (bench_ray_integration; thread CPU time)"
"$bin/bench_ray_integration" --repeat 5
echo

echo "## maze_mapper run, generated 16x16 (--seed 1), --quiet, best of 5"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin/maze_mapper" generate 16x16 --seed 1 -o "$work/m16.txt" >/dev/null
best=""
for _ in 1 2 3 4 5; do
    t0=$(date +%s%N)
    "$bin/maze_mapper" run "$work/m16.txt" --quiet >/dev/null
    t1=$(date +%s%N)
    ms=$(( (t1 - t0) / 1000000 ))
    if [ -z "$best" ] || [ "$ms" -lt "$best" ]; then best=$ms; fi
done
echo "run_16x16_wall_ms: $best (target < 50)"
echo

echo "## Exploration at scale (bench/scale.sh)"
bench/scale.sh "$bin/maze_mapper" "$@"
