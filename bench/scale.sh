#!/bin/sh
# Exploration at scale: generates perfect mazes of 64^2, 256^2, 512^2 and 1024^2
# cells (fixed seeds), runs `maze_mapper run FILE --quiet` (default robot, model and
# strategy) under /usr/bin/time -v and prints one table row per size.
#
#   bench/scale.sh [MAZE_MAPPER] [SIZE ...]
#     MAZE_MAPPER  the program (default build/bench/bin/maze_mapper, then build/release/bin/)
#     SIZE         cells per side (default 64 256 512 1024)
#
# Columns: size, wall time (s), CPU time (user + sys, s; steadier than wall on a busy
# machine), visited cells, moves, wall time per visited cell (us), peak RSS (MiB).
set -eu

here=$(cd "$(dirname "$0")/.." && pwd)
prog=${1:-}
if [ -n "$prog" ]; then shift; fi
if [ -z "$prog" ]; then
    for p in "$here/build/bench/bin/maze_mapper" "$here/build/release/bin/maze_mapper"; do
        if [ -x "$p" ]; then prog=$p; break; fi
    done
fi
if [ -z "$prog" ] || [ ! -x "$prog" ]; then
    echo "error: no maze_mapper (build the bench or release preset first)" >&2
    exit 2
fi
if [ ! -x /usr/bin/time ]; then
    echo "error: /usr/bin/time is missing (Debian package 'time')" >&2
    exit 2
fi
sizes=${*:-64 256 512 1024}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf '%-11s %9s %9s %9s %9s %12s %13s  %s\n' size wall_s cpu_s visited moves us_per_cell peak_rss_MiB end
for n in $sizes; do
    maze="$work/maze$n.txt"
    "$prog" generate "${n}x${n}" --seed "$n" -o "$maze" >/dev/null
    /usr/bin/time -v -o "$work/time$n" "$prog" run "$maze" --quiet --max-steps 1000000000 >"$work/out$n"
    wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {print $2}' "$work/time$n" |
           awk -F: '{ s = 0; for (i = 1; i <= NF; i++) s = s * 60 + $i; print s }')
    cpu=$(awk -F': ' '/User time|System time/ {s += $2} END {print s}' "$work/time$n")
    rss=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$work/time$n")
    visited=$(awk '/^visited:/ {print $2}' "$work/out$n")
    moves=$(awk '/^moves:/ {print $2}' "$work/out$n")
    end=$(awk -F': ' '/^end:/ {print $2}' "$work/out$n")
    awk -v n="$n" -v w="$wall" -v c="$cpu" -v v="$visited" -v m="$moves" -v r="$rss" -v e="$end" 'BEGIN {
        printf "%-11s %9.2f %9.2f %9d %9d %12.1f %13.1f  %s\n", n "x" n, w, c, v, m, w * 1e6 / v, r / 1024, e }'
done
