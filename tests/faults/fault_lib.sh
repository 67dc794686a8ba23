# The fault suites' shared steps (sourced by a suite run as SUITE PROGRAM SOURCE_DIR): the
# program and source folder from the suite's arguments (the working folder then SOURCE_DIR),
# a scratch folder removed at exit, a case's start and failure, waits with a bound, and what
# "whole" means for a file (whole_outputs.sh).
program=$1
source_dir=$2
cd "$source_dir" || exit 1
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
failures=0
count=0

fail() {
  failures=$((failures + 1))
  printf 'FAIL: %s: %s\n' "$case_name" "$1"
}
begin() {
  [ -z "${case_name:-}" ] || printf '%4ss  %s\n' "$(($(date +%s) - case_started))" "$case_name"
  case_started=$(date +%s)
  case_name=$1
  count=$((count + 1))
  dir="$scratch/$count"
  mkdir -p "$dir"
}
# No temporary left anywhere under the case's directory.
no_temporaries() {
  left=$(find "$dir" -name '.*.tmp.*' 2>/dev/null)
  [ -z "$left" ] || fail "temporaries left: $left"
}
# Waits (at most ~20 s) until `test "$@"` holds.
wait_for() {
  tries=0
  until test "$@"; do
    tries=$((tries + 1))
    [ "$tries" -lt 400 ] || return 1
    sleep 0.05
  done
}
# Waits until file $1 contains the text $2 (at most ~20 s).
wait_for_text() {
  tries=0
  until grep -q "$2" "$1" 2>/dev/null; do
    tries=$((tries + 1))
    [ "$tries" -lt 400 ] || return 1
    sleep 0.05
  done
}
. "$source_dir/tests/faults/whole_outputs.sh"  # ends_whole, png_whole

# Waits (at most ~20 s) until process $1 holds file $2 open.
wait_opened() {
  tries=0
  until ls -l "/proc/$1/fd" 2>/dev/null | grep -qF -- "-> $2"; do
    tries=$((tries + 1))
    [ "$tries" -lt 400 ] || return 1
    sleep 0.05
  done
}
# Ends process $1 with SIGKILL unless it ends within $2 seconds; prints the watchdog's pid.
watchdog() {
  (sleep "$2"; kill -KILL "$1" 2>/dev/null) >/dev/null 2>&1 &
  echo $!
}

# Waits (at most ~20 s) until process $1 has used the CPU and then none for a second: it
# waits on something (here: a full pipe).
wait_idle() {
  tries=0
  last=-1
  still=0
  while [ "$tries" -lt 400 ]; do
    ticks=$(awk '{ print $14 + $15 }' "/proc/$1/stat" 2>/dev/null) || return 1
    if [ "$ticks" = "$last" ] && [ "$ticks" -gt 0 ]; then still=$((still + 1)); else still=0; fi
    [ "$still" -lt 20 ] || return 0
    last=$ticks
    tries=$((tries + 1))
    sleep 0.05
  done
  return 1
}
