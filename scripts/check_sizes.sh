#!/bin/sh
# Lists the classes over 160 lines, functions over 70 and source files over 450 in the
# project's own sources (common, maze, controller, app), and fails when there is one: the
# sizes a reader can hold in mind. Needs universal-ctags (scripts/install-test-deps.sh).
# Usage: scripts/check_sizes.sh [SOURCE_DIR]
set -eu
cd "${1:-$(dirname "$0")/..}"
dirs="common maze controller app"
status=0

too_long=$(ctags -x --c++-kinds=fcsm --fields=+ne --_xformat="%{line} %{end} %{kind} %{input} %{name}" \
    -R --languages=C++ $dirs |
  awk '$2 != "-" {
         n = $2 - $1 + 1
         limit = ($3 == "function" || $3 == "member") ? 70 : 160
         if (($3 == "function" || $3 == "member" || $3 == "class" || $3 == "struct") && n > limit)
           printf "%s:%s: %s %s is %d lines (at most %d)\n", $4, $1, $3, $5, n, limit
       }')
if [ -n "$too_long" ]; then
  echo "$too_long"
  status=1
fi

for f in $(find $dirs -name '*.cpp' -o -name '*.hpp' | sort); do
  n=$(wc -l < "$f")
  if [ "$n" -gt 450 ]; then
    echo "$f: $n lines (at most 450)"
    status=1
  fi
done
[ "$status" -eq 0 ] && echo "sizes: every class <= 160 lines, function <= 70, source file <= 450"
exit "$status"
