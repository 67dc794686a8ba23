#!/bin/sh
# Installs the Debian 12 packages the benchmarks need on top of scripts/install-deps.sh:
# Google Benchmark (bench/), OctoMap (the library bench_ray_integration compares against),
# the `time` program (bench/scale.sh) and perf/valgrind for profiling. maze_mapper itself
# needs none of them.
exec "$(dirname "$0")/install-deps.sh" libbenchmark-dev liboctomap-dev time linux-perf valgrind "$@"
