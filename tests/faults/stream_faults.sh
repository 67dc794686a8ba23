#!/bin/sh
# The standard streams and the --out directory under faults: a closed or failing stream never
# mixes into a file nor aborts, a wait on a stream or a prompt still ends on a signal, a run a
# signal stopped writes its files within a bounded time, and an --out directory's entries that
# a run cannot own are refused before the robot moves, untouched.
#   usage: stream_faults.sh PROGRAM SOURCE_DIR
set -u
. "$2/tests/faults/fault_lib.sh"  # program, source_dir, the scratch folder, the case steps

lab=worlds/lab4x4.txt
"$program" generate 160x160 --seed 2 -o "$scratch/maze160.txt" || exit 1
mms_program="python3 examples/mms/floodfill.py"

# --- Closed and failing streams ----------------------------------------------------------

begin "a closed standard output: the trace gets no printed map, the run ends 0"
"$program" run "$lab" --out "$dir/ref" >/dev/null 2>&1 || fail "the reference run failed"
status=0
"$program" run "$lab" --out "$dir/out" >&- 2>"$dir/err" || status=$?
[ "$status" = 0 ] || fail "exit $status: $(cat "$dir/err")"
cmp -s "$dir/ref/trace.csv" "$dir/out/trace.csv" || fail "trace.csv differs: $(head -2 "$dir/out/trace.csv")"
grep -q '"steps"' "$dir/out/summary.json" || fail "summary.json lost"

begin "a closed standard error: a bad world is exit 2, a good run exit 0, no abort"
status=0
"$program" run "$dir/nonexistent.txt" 2>&- >"$dir/out" || status=$?
[ "$status" = 2 ] || fail "a missing world: exit $status, expected 2"
status=0
"$program" run "$lab" --quiet --out "$dir/o1" 2>&- >"$dir/out" || status=$?
[ "$status" = 0 ] || fail "a good run: exit $status, expected 0"
[ -s "$dir/o1/summary.json" ] || fail "no summary.json"

begin "standard error on a full device: the run's status, its files written"
status=0
"$program" run "$lab" --quiet --out "$dir/o1" 2>/dev/full >"$dir/out" || status=$?
[ "$status" = 0 ] || fail "exit $status, expected 0"
grep -q "^end: " "$dir/out" || fail "no summary"
status=0
"$program" run "$dir/nonexistent.txt" 2>/dev/full || status=$?
[ "$status" = 2 ] || fail "a missing world: exit $status, expected 2"

begin "an mms transcript into a pipe whose reader has gone: the run goes on to its end"
# (the algorithm's own stderr to /dev/null: this is about the transcript, not the algorithm)
{ "$program" mms "$lab" --quiet --transcript -- sh -c "exec $mms_program 2>/dev/null" 2>&1 >"$dir/out"
  echo $? >"$dir/status"; } | head -c 0
[ "$(cat "$dir/status")" = 0 ] || fail "exit $(cat "$dir/status"), expected 0"
grep -q "^end: " "$dir/out" || fail "no summary: $(tail -2 "$dir/out")"

# --- Waits that end on a signal ----------------------------------------------------------

# `COMMAND 2>FIFO` where the FIFO's reader has filled it and never reads: every message waits.
begin "SIGTERM while standard error waits on a full pipe: mms --transcript, batch of broken files exit 143"
printf 'o---o\n| x\n' >"$dir/broken1.txt"
cp "$dir/broken1.txt" "$dir/broken2.txt"
for cmd in mms batch; do
  rm -f "$dir/stderr"
  mkfifo "$dir/stderr"
  exec 3<>"$dir/stderr"  # the reader that never reads
  dd if=/dev/zero of="$dir/stderr" bs=4096 count=1024 oflag=nonblock 2>/dev/null  # fills the pipe
  case $cmd in
    mms) "$program" mms "$lab" --transcript -- $mms_program >"$dir/out" 2>"$dir/stderr" 3<&- & ;;
    batch) "$program" batch "$dir/broken1.txt" "$dir/broken2.txt" "$lab" >"$dir/out" 2>"$dir/stderr" 3<&- & ;;
  esac
  pid=$!
  guard=$(watchdog "$pid" 60)
  wait_idle "$pid" || fail "$cmd: never waited"
  kill -TERM "$pid"
  status=0
  wait "$pid" || status=$?
  kill "$guard" 2>/dev/null
  exec 3<&-
  [ "$status" = 143 ] || fail "$cmd: exit $status, expected 143"
done
no_temporaries

# $1 signal name, $2 expected status: run --step waiting for a line nobody types.
signal_at_step_prompt() {
  begin "SIG$1 while run --step waits for a line: exit $2, the summary says so"
  mkfifo "$dir/stdin"
  exec 4<>"$dir/stdin"  # a writer that never writes
  "$program" run "$lab" --step --out "$dir/out" <"$dir/stdin" >"$dir/stdout" 2>"$dir/err" 4<&- &
  pid=$!
  guard=$(watchdog "$pid" 30)
  wait_idle "$pid" || fail "never waited"
  kill -"$1" "$pid"
  status=0
  wait "$pid" || status=$?
  kill "$guard" 2>/dev/null
  exec 4<&-
  [ "$status" = "$2" ] || fail "exit $status, expected $2"
  grep -q "^end: stopped (interrupted by $3)" "$dir/stdout" || fail "end line: $(grep '^end' "$dir/stdout")"
  ends_whole "$dir/out/trace.csv" || fail "trace.csv cut"
  no_temporaries
}
signal_at_step_prompt TERM 143 SIGTERM
signal_at_step_prompt INT 130 Ctrl-C

# A run stopped by SIGTERM whose replay.html is a FIFO a reader holds and never reads: the
# write would wait for ever; the files get 2 s from the first one written.
begin "SIGTERM during a run: the summary first, then 2 s for the files, the rest left out and named"
mkdir -p "$dir/out"
mkfifo "$dir/out/replay.html"
exec 5<>"$dir/out/replay.html"
"$program" run "$scratch/maze160.txt" --quiet --out "$dir/out" >"$dir/stdout" 2>"$dir/err" 5<&- &
pid=$!
guard=$(watchdog "$pid" 60)
tries=0
until ls -a "$dir/out" | grep -q '^\.trace\.csv\.tmp\.'; do
  tries=$((tries + 1))
  [ "$tries" -lt 400 ] || break
  sleep 0.05
done
sleep 0.5
signalled=$(date +%s)
kill -TERM "$pid"
status=0
wait "$pid" || status=$?
ended=$(date +%s)
kill "$guard" 2>/dev/null
exec 5<&-
[ "$status" = 143 ] || fail "exit $status, expected 143"
[ $((ended - signalled)) -le 10 ] || fail "$((ended - signalled)) s from the signal to the end"
grep -q "^end: stopped (interrupted by SIGTERM)" "$dir/stdout" || fail "no summary: $(tail -3 "$dir/stdout")"
grep -q "not written within 2 s of it are left out (written: summary.json, trace.csv" "$dir/err" ||
  fail "message: $(cat "$dir/err")"
ends_whole "$dir/out/summary.json" || fail "summary.json cut"
ends_whole "$dir/out/trace.csv" || fail "trace.csv cut"
[ -p "$dir/out/replay.html" ] || fail "the FIFO was replaced"
no_temporaries

# --- What an --out directory holds that a run cannot own ----------------------------------

begin "an output's name that is a symbolic link in --out: refused before the run, link and target untouched"
mkdir -p "$dir/d1"
echo precious >"$dir/precious.png"
ln -s ../precious.png "$dir/d1/map.png"
echo kept >"$dir/precious.csv"
ln -s ../precious.csv "$dir/d1/plan.csv"  # a name this run does not write: not cleaned away either
status=0
"$program" run "$lab" --out "$dir/d1" >"$dir/stdout" 2>"$dir/err" || status=$?
[ "$status" = 2 ] || fail "exit $status, expected 2"
grep -q "^error: --out $dir/d1: map.png is a symbolic link (to ../precious.png)" "$dir/err" || fail "message: $(cat "$dir/err")"
[ ! -s "$dir/stdout" ] || fail "the robot moved: $(head -2 "$dir/stdout")"
[ -L "$dir/d1/map.png" ] && [ -L "$dir/d1/plan.csv" ] || fail "a link was removed"
[ "$(cat "$dir/precious.png")" = precious ] && [ "$(cat "$dir/precious.csv")" = kept ] || fail "a target was written"

begin "a plain file named snapshots in --out: refused before the run, the file untouched"
mkdir -p "$dir/d2"
echo mine >"$dir/d2/snapshots"
status=0
"$program" run "$lab" --out "$dir/d2" --snapshots 2 >"$dir/stdout" 2>"$dir/err" || status=$?
[ "$status" = 2 ] || fail "exit $status, expected 2"
grep -q "^error: --out $dir/d2: snapshots is not a directory" "$dir/err" || fail "message: $(cat "$dir/err")"
[ ! -s "$dir/stdout" ] || fail "the robot moved"
[ "$(cat "$dir/d2/snapshots")" = mine ] || fail "the file changed"

begin ""
echo "$((count - 1)) stream and --out cases, $failures failed"
[ "$failures" -eq 0 ]
