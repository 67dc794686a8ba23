#!/bin/sh
# Runs every case of cases.txt: `ARGS... => EXPECTED` runs `PROGRAM ARGS...` in the source
# tree and expects exit status 2, nothing on standard output, and standard error exactly
# EXPECTED and a newline. `ARGS... ~> EXPECTED` is a warning: exit status 0, standard error
# exactly EXPECTED and a newline (besides the `wrote DIR/` line of an --out), standard
# output whatever the command prints. Arguments
# are split on blanks (no quoting). @TMP@ in a case stands for a scratch directory of this
# run (emptied after each case; an error case must leave nothing in it: no half-written
# output). Reports every failing case, then fails if there was one.
# With MAZE_MAPPER_UPDATE_GOLDEN=1 the expectations are rewritten from what the program
# prints (review `git diff tests/bad_inputs` after that).
#   usage: run_bad_inputs.sh PROGRAM SOURCE_DIR
set -eu
program=$1
source_dir=$2
cases="$source_dir/tests/bad_inputs/cases.txt"
cd "$source_dir"
set -f
failures=0
count=0
updated=$(mktemp)
out=$(mktemp)
err=$(mktemp)
scratch=$(mktemp -d)
trap 'rm -f "$updated" "$out" "$err"; rm -rf "$scratch"' EXIT
while IFS= read -r line || [ -n "$line" ]; do
  case $line in
    ''|'#'*) printf '%s\n' "$line" >>"$updated"; continue ;;
  esac
  arrow='=>'
  want_status=2
  case $line in
    *' ~> '*) arrow='~>'; want_status=0 ;;
  esac
  args=${line%% "$arrow" *}
  expected=${line#* "$arrow" }
  count=$((count + 1))
  status=0
  # shellcheck disable=SC2086  # the arguments are split on blanks on purpose
  "$program" $(printf '%s' "$args" | sed "s|@TMP@|$scratch|g") >"$out" 2>"$err" </dev/null || status=$?
  # A warning's command goes on: the `wrote DIR/: ...` line of its --out is not the warning.
  if [ "$arrow" = '~>' ]; then
    grep -v '^wrote ' "$err" >"$err.warning" || true
    mv "$err.warning" "$err"
  fi
  actual=$(sed "s|$scratch|@TMP@|g" "$err")
  left=$(ls -A "$scratch")
  rm -rf "$scratch" && mkdir "$scratch"
  printf '%s %s %s\n' "$args" "$arrow" "$actual" >>"$updated"
  problem=""
  [ "$status" -eq "$want_status" ] || problem="exit status $status, expected $want_status"
  [ "$want_status" -ne 2 ] || [ ! -s "$out" ] || problem="${problem:+$problem; }something on standard output"
  [ "$(wc -l <"$err")" -eq 1 ] || problem="${problem:+$problem; }standard error is not one line"
  [ "$actual" = "$expected" ] || problem="${problem:+$problem; }message differs"
  [ "$want_status" -ne 2 ] || [ -z "$left" ] || problem="${problem:+$problem; }left files behind: $left"
  if [ -n "$problem" ]; then
    failures=$((failures + 1))
    printf 'FAIL: %s\n  %s\n  expected: %s\n  actual:   %s\n' "$args" "$problem" "$expected" "$actual"
  fi
done <"$cases"
if [ "${MAZE_MAPPER_UPDATE_GOLDEN:-0}" = 1 ]; then
  cp "$updated" "$cases"
  echo "updated $cases"
  exit 0
fi
echo "$count bad-input cases, $failures failed"
[ "$failures" -eq 0 ]
