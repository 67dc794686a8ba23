#!/bin/sh
# The fault-and-signal suite: what the program writes to, and how it stops. Every case
# asserts that nothing the user pointed at is destroyed, that no file is left half-written
# (no ".NAME.tmp.PID" temporary survives, every output present is whole), and the exit
# status. Run as root in CI (the device cases use mknod then; /dev/null is checked as well).
# Signals are sent once the process has reported the phase they aim at (its output, the
# files it has written), not after a guessed sleep, except the batch case (see there).
#   usage: run_faults.sh PROGRAM SOURCE_DIR
set -u
. "$2/tests/faults/fault_lib.sh"  # program, source_dir, the scratch folder, the case steps

lab=worlds/lab4x4.txt
"$program" generate 24x24 --seed 3 -o "$scratch/maze24.txt" || exit 1
"$program" generate 64x64 --seed 5 -o "$scratch/maze64.txt" || exit 1
"$program" generate 256x256 --seed 1 -o "$scratch/maze256.txt" || exit 1

# --- Writes that respect their target ---------------------------------------------------

begin "a character device stays a device (/dev/null)"
"$program" batch "$lab" --csv /dev/null >/dev/null 2>"$dir/err" || fail "batch --csv /dev/null failed: $(cat "$dir/err")"
[ -c /dev/null ] || fail "/dev/null is no longer a character device"
"$program" batch "$lab" --csv "$dir/part.csv" >/dev/null 2>&1
"$program" batch merge "$dir/part.csv" -o /dev/null >/dev/null 2>"$dir/err" || fail "batch merge -o /dev/null failed: $(cat "$dir/err")"
[ -c /dev/null ] || fail "/dev/null is no longer a character device"

if [ "$(id -u)" = 0 ]; then
  begin "a device node of our own, as root"
  mknod "$dir/null.csv" c 1 3 || fail "mknod"
  "$program" batch "$lab" --csv "$dir/null.csv" >/dev/null 2>&1 || fail "batch --csv DEVICE failed"
  [ -c "$dir/null.csv" ] || fail "the device node was replaced"
  no_temporaries
fi

begin "a FIFO stays a FIFO and its reader gets the content"
mkfifo "$dir/fifo.txt"
cat "$dir/fifo.txt" >"$dir/got" &
reader=$!
"$program" generate 4x4 --seed 9 -o "$dir/fifo.txt" 2>"$dir/err" || fail "generate -o FIFO failed: $(cat "$dir/err")"
wait "$reader"
[ -p "$dir/fifo.txt" ] || fail "the FIFO was replaced"
"$program" generate 4x4 --seed 9 >"$dir/want"
cmp -s "$dir/got" "$dir/want" || fail "the FIFO's reader did not get the maze"
no_temporaries

begin "a symbolic link stays a link and its target gets the content"
printf 'old\n' >"$dir/target.txt"
ln -s target.txt "$dir/link.txt"
"$program" generate 4x4 --seed 9 -o "$dir/link.txt" 2>"$dir/err" || fail "generate -o LINK failed: $(cat "$dir/err")"
[ -L "$dir/link.txt" ] || fail "the link was replaced by a file"
"$program" generate 4x4 --seed 9 >"$dir/want"
cmp -s "$dir/target.txt" "$dir/want" || fail "the link's target does not hold the maze"
ln -s missing.txt "$dir/dangling.txt"
"$program" convert "$lab" "$dir/dangling.txt" 2>"$dir/err" || fail "convert to a dangling link failed: $(cat "$dir/err")"
[ -L "$dir/dangling.txt" ] && [ -f "$dir/missing.txt" ] || fail "a dangling link's target was not created through it"
no_temporaries

begin "an output that is an input is refused before anything runs"
cp "$lab" "$dir/a.txt"
status=0
"$program" batch "$dir/a.txt" --csv "$dir/a.txt" >"$dir/out" 2>"$dir/err" || status=$?
[ "$status" = 2 ] || fail "batch a.txt --csv a.txt: exit $status, expected 2"
grep -q "^error: --csv .*a.txt is also an input: refusing to overwrite it$" "$dir/err" || fail "message: $(cat "$dir/err")"
cmp -s "$dir/a.txt" "$lab" || fail "a.txt changed"
ln -s a.txt "$dir/alias.txt"
status=0
"$program" convert "$dir/a.txt" "$dir/alias.txt" 2>"$dir/err" || status=$?
[ "$status" = 2 ] || fail "convert a.txt alias-of-a.txt: exit $status, expected 2"
cmp -s "$dir/a.txt" "$lab" || fail "a.txt changed by convert"
"$program" batch "$lab" --csv "$dir/part.csv" >/dev/null 2>&1
status=0
"$program" batch merge "$dir/part.csv" -o "$dir/part.csv" >/dev/null 2>&1 || status=$?
[ "$status" = 2 ] || fail "batch merge X -o X: exit $status, expected 2"
no_temporaries

begin "a full device (/dev/full) is exit status 4, said once"
"$program" batch "$lab" --csv "$dir/part.csv" >/dev/null 2>&1
status=0
"$program" batch merge "$dir/part.csv" -o /dev/full >/dev/null 2>"$dir/err" || status=$?
[ "$status" = 4 ] || fail "batch merge -o /dev/full: exit $status, expected 4"
grep -q "^error: cannot write /dev/full: No space left on device$" "$dir/err" || fail "message: $(cat "$dir/err")"
[ -c /dev/full ] || fail "/dev/full is no longer a device"

begin "a full disk under --out: exit status 4, the summary still printed, no temporary left"
mkdir -p "$dir/tiny"
# A 16 KiB tmpfs in a mount namespace of its own (root only; skipped where mounting is not allowed).
if unshare -m sh -c "mount -t tmpfs -o size=16k tmpfs '$dir/tiny' && exit 0" 2>/dev/null; then
  status=0
  unshare -m sh -c "mount -t tmpfs -o size=16k tmpfs '$dir/tiny' && '$program' run '$lab' --quiet --trace-steps \
    --out '$dir/tiny/out' >'$dir/out' 2>'$dir/err'; status=\$?; ls -A '$dir/tiny/out' >'$dir/left'; exit \$status" ||
    status=$?
  [ "$status" = 4 ] || fail "exit $status, expected 4"
  grep -q "^end: done" "$dir/out" || fail "no summary"
  grep -q "^error: cannot write .*: No space left on device$" "$dir/err" || fail "message: $(cat "$dir/err")"
  ! grep -q '\.tmp\.' "$dir/left" || fail "temporaries left: $(cat "$dir/left")"
else
  echo "     (skipped: mounting a tmpfs is not allowed here)"
fi

begin "a full disk under --out: mms, compare and plan print their summary too, exit status 4"
mkdir -p "$dir/tiny"
if unshare -m sh -c "mount -t tmpfs -o size=16k tmpfs '$dir/tiny' && exit 0" 2>/dev/null; then
  for cmd in "mms --quiet" "compare --quiet" "plan"; do
    case $cmd in mms*) algorithm="-- sh -c 'exit 0'" want="^end: exited" ;; compare*) algorithm="" want="^coverage " ;;
      *) algorithm="" want="^end: done" ;; esac
    status=0
    unshare -m sh -c "mount -t tmpfs -o size=16k tmpfs '$dir/tiny' && '$program' $cmd '$lab' --out '$dir/tiny/out' \
      $algorithm >'$dir/out' 2>'$dir/err'" || status=$?
    [ "$status" = 4 ] || fail "$cmd: exit $status, expected 4"
    grep -q "$want" "$dir/out" || fail "$cmd: no summary"
    grep -q "^error: cannot write .*: No space left on device$" "$dir/err" || fail "$cmd: message: $(cat "$dir/err")"
  done
else
  echo "     (skipped: mounting a tmpfs is not allowed here)"
fi

begin "standard output on a full device (/dev/full): exit status 4 in every command, said once"
for cmd in "run --quiet" "plan" "compare --quiet" "mms --quiet"; do
  status=0
  case $cmd in
    mms*) "$program" $cmd "$lab" -- sh -c 'exit 0' >/dev/full 2>"$dir/err" || status=$? ;;
    *) "$program" $cmd "$lab" >/dev/full 2>"$dir/err" || status=$? ;;
  esac
  [ "$status" = 4 ] || fail "$cmd >/dev/full: exit $status, expected 4"
  [ "$(cat "$dir/err")" = "error: cannot write standard output: No space left on device" ] ||
    fail "$cmd: message: $(cat "$dir/err")"
done

begin "a dangling symbolic link as --out is refused and left as it is"
ln -s missing "$dir/out"
for out in "$dir/out" "$dir/out/sub"; do
  status=0
  "$program" run "$lab" --quiet --out "$out" >/dev/null 2>"$dir/err" || status=$?
  [ "$status" = 2 ] || fail "--out $out: exit $status, expected 2"
  [ -L "$dir/out" ] || fail "--out $out: the link was removed"
  [ ! -e "$dir/missing" ] || fail "--out $out: the link's target was made"
done
grep -q "^error: --out .*out/sub: cannot create the directory" "$dir/err" || fail "message: $(cat "$dir/err")"
"$program" run "$lab" --quiet --out "$dir/out" >/dev/null 2>"$dir/err"
grep -qx "error: --out $dir/out: a symbolic link to missing, which does not exist (create that directory, or give another path)" \
  "$dir/err" || fail "message: $(cat "$dir/err")"

# $1 the input's description in the message, $2 the input's path, then the command line.
refused_as_input() {
  what=$1 input=$2
  shift 2
  cp "$input" "$dir/before"
  status=0
  "$program" "$@" >/dev/null 2>"$dir/err" || status=$?
  [ "$status" = 2 ] || fail "$*: exit $status, expected 2"
  grep -qx "error: --out $input is also an input ($what $input): refusing to overwrite it" "$dir/err" ||
    fail "$*: message: $(cat "$dir/err")"
  cmp -s "$input" "$dir/before" || fail "$*: $input changed"
}
begin "an input in --out under an output's name is refused before anything runs, and kept"
mkdir -p "$dir/o"
"$program" robot hambot >"$dir/o/summary.json"
refused_as_input --robot "$dir/o/summary.json" run "$lab" --quiet --robot "$dir/o/summary.json" --out "$dir/o"
cp "$lab" "$dir/o/trace.csv"
refused_as_input "the world" "$dir/o/trace.csv" run "$dir/o/trace.csv" --quiet --out "$dir/o"
printf 'exit 0\n' >"$dir/o/marks.txt"
refused_as_input "the program's argument" "$dir/o/marks.txt" mms "$lab" --quiet --out "$dir/o" -- sh "$dir/o/marks.txt"
cp tests/data/logs/room_depth.csv "$dir/o/logodds.csv"
refused_as_input "the log" "$dir/o/logodds.csv" map-log "$dir/o/logodds.csv" --cells 12,12 --boundary 0,6,0,6 --out "$dir/o"
cp worlds/open_room6x6.txt "$dir/o/thresholded.txt"
refused_as_input "the world" "$dir/o/thresholded.txt" room "$dir/o/thresholded.txt" --quiet --out "$dir/o"
mkdir -p "$dir/o/k5"
"$program" robot hambot >"$dir/o/k5/map.yaml"
refused_as_input --robot "$dir/o/k5/map.yaml" compare "$lab" --quiet --robot "$dir/o/k5/map.yaml" --out "$dir/o"
[ ! -e "$dir/o/map.png" ] && [ ! -e "$dir/o/k3" ] || fail "a refused command wrote: $(ls "$dir/o")"
no_temporaries

# --- --out owns its directory's outputs -------------------------------------------------

begin "a reused --out loses the files this run does not write, and nothing else"
mkdir -p "$dir/out/snapshots"
for f in trace.csv replay.html plan.png plan.csv snapshots/04.png; do printf 'stale\n' >"$dir/out/$f"; done
printf 'mine\n' >"$dir/out/notes.txt"
"$program" run "$lab" --out "$dir/out" --no-trace --no-replay >/dev/null 2>&1 || fail "run failed"
for f in trace.csv replay.html plan.png plan.csv snapshots/04.png snapshots; do
  [ ! -e "$dir/out/$f" ] || fail "stale $f kept"
done
[ -f "$dir/out/notes.txt" ] || fail "a file of the user's removed"
[ -f "$dir/out/summary.json" ] || fail "no summary.json"

# --- Smaller items: each seen once, each checked here --------------------------------------

begin "a CSV of batch whose path holds a newline merges back"
mkdir -p "$dir/folder"
nl_name="$dir/folder/two
lines.txt"
cp "$lab" "$nl_name"
"$program" batch "$dir/folder" --csv "$dir/rows.csv" >/dev/null 2>&1 || fail "batch of a folder failed"
"$program" batch merge "$dir/rows.csv" -o "$dir/merged.csv" >/dev/null 2>"$dir/err" || fail "merge: $(cat "$dir/err")"
cmp -s "$dir/rows.csv" "$dir/merged.csv" || fail "the merged CSV differs from the part"

begin "a folder's subfolders, dangling links and FIFOs are named, not skipped silently"
mkdir -p "$dir/folder/sub"
cp "$lab" "$dir/folder/a.txt"
ln -s missing.txt "$dir/folder/gone.txt"
mkfifo "$dir/folder/pipe.txt"
"$program" batch "$dir/folder" >"$dir/out" 2>&1 || fail "batch failed"
for said in "gone.txt (a dangling link)" "pipe.txt (a FIFO)" "sub (a folder: folders are not searched)"; do
  grep -qF "$said" "$dir/out" || fail "not named: $said"
done

begin "floodfill that cannot reach its goal does not end done"
status=0
"$program" run tests/faults/walled_goal.txt --strategy floodfill --quiet >"$dir/out" 2>&1 || status=$?
[ "$status" = 1 ] || fail "exit $status, expected 1"
grep -q "^end: incomplete" "$dir/out" || fail "$(grep '^end' "$dir/out")"

begin "a .num world with a UTF-8 BOM reads as without"
"$program" show tests/faults/bom.num >"$dir/bom" 2>&1 || fail "$(cat "$dir/bom")"
"$program" show worlds/lab4x4.num >"$dir/plain" 2>&1
cmp -s "$dir/bom" "$dir/plain" || fail "the BOM changed what is read"

begin "--stuck-bumper with a model that reads no bumper is a warning"
"$program" run "$lab" --quiet --max-steps 1 --model depth --stuck-bumper "bumper front" >/dev/null 2>"$dir/err"
grep -qx "warning: --stuck-bumper has no effect with the depth model (read by bump)" "$dir/err" || fail "$(cat "$dir/err")"

# --- Signals ----------------------------------------------------------------------------

# $1 signal name, $2 expected status: run on a big maze, signalled once it prints its map.
signal_in_run_loop() {
  begin "SIG$1 in the run loop: exit $2, the files whole, the trace a row a step"
  "$program" run "$scratch/maze64.txt" --out "$dir/out" --no-replay --trace-steps >"$dir/stdout" 2>"$dir/err" &
  pid=$!
  wait_for_text "$dir/stdout" "^step" || fail "the run printed no step"
  kill -"$1" "$pid"
  status=0
  wait "$pid" || status=$?
  [ "$status" = "$2" ] || fail "exit $status, expected $2"
  grep -q '"end": "stopped"' "$dir/out/summary.json" || fail "summary.json does not say stopped"
  steps=$(sed -n 's/^ *"steps": \([0-9]*\),$/\1/p' "$dir/out/summary.json")
  rows=$(($(wc -l <"$dir/out/trace.csv") - 1))
  [ "$rows" = "$steps" ] || fail "trace.csv has $rows rows for $steps steps"
  ends_whole "$dir/out/trace.csv" || fail "trace.csv cut"
  # The files after summary.json and trace.csv get 2 s: on a loaded machine map.png may be
  # left out, and the one line then says what was written.
  if [ -e "$dir/out/map.png" ]; then
    png_whole "$dir/out/map.png" || fail "map.png cut"
  else
    grep -q "left out (written: summary.json, trace.csv" "$dir/err" || fail "map.png missing, unsaid: $(cat "$dir/err")"
  fi
  no_temporaries
}
signal_in_run_loop INT 130
signal_in_run_loop TERM 143
signal_in_run_loop HUP 129

begin "SIGINT in a room run without --out: exit 130, its summary, no word of files"
"$program" room worlds/ir_room.room --strategy wander --time-limit 100000 --snapshot-steps 1 >"$dir/stdout" 2>"$dir/err" &
pid=$!
wait_for_text "$dir/stdout" "^--- step 1:" || fail "the room run printed no snapshot"
kill -INT "$pid"
status=0
wait "$pid" || status=$?
[ "$status" = 130 ] || fail "exit $status, expected 130"
grep -q "^end: stopped (interrupted by Ctrl-C)" "$dir/stdout" || fail "no summary saying so: $(tail -3 "$dir/stdout")"
! grep -q "output files" "$dir/err" || fail "speaks of output files it never had: $(cat "$dir/err")"

begin "SIGTERM while the files are written (a FIFO holds the writer): exit 143, nothing half-written"
mkdir -p "$dir/out"
mkfifo "$dir/out/replay.html"
"$program" run "$lab" --out "$dir/out" >/dev/null 2>"$dir/err" &
pid=$!
wait_for -f "$dir/out/summary.json" || fail "summary.json never came"
kill -TERM "$pid"
status=0
wait "$pid" || status=$?
[ "$status" = 143 ] || fail "exit $status, expected 143"
[ -p "$dir/out/replay.html" ] || fail "the FIFO was replaced"
ends_whole "$dir/out/trace.csv" || fail "trace.csv cut"
ends_whole "$dir/out/summary.json" || fail "summary.json cut"
no_temporaries

begin "SIGTERM while batch waits to write its CSV (a FIFO without a reader): exit 143"
mkfifo "$dir/rows.csv"
"$program" batch "$lab" --csv "$dir/rows.csv" >"$dir/stdout" 2>"$dir/err" &
pid=$!
wait_for_text "$dir/stdout" "^totals\|worlds" || fail "batch printed no table"
kill -TERM "$pid"
status=0
wait "$pid" || status=$?
[ "$status" = 143 ] || fail "exit $status, expected 143"
[ -p "$dir/rows.csv" ] || fail "the FIFO was replaced"

# The one timed case: batch prints nothing until its runs end, so the signal comes two
# seconds in, when the 4x4 world has long finished (25 ms; a second was once too little on a
# loaded machine) and the 256x256 one (5 s on an idle machine) is running.
begin "SIGTERM of a batch keeps its finished rows"
# The second world's run is still going when the signal comes: the same 256² maze twice takes
# seconds at any speed, lab4x4 well under one.
"$program" batch "$lab" "$scratch/maze256.txt" "$scratch/maze256.txt" --jobs 1 --csv "$dir/rows.csv" >"$dir/stdout" 2>"$dir/err" &
pid=$!
sleep 1
kill -TERM "$pid"
status=0
wait "$pid" || status=$?
[ "$status" = 143 ] || fail "exit $status, expected 143"
[ "$(wc -l <"$dir/rows.csv")" = 2 ] || fail "rows.csv: $(cat "$dir/rows.csv")"
grep -q "lab4x4" "$dir/rows.csv" || fail "the finished row is not in rows.csv"
no_temporaries


begin "SIGTERM while a FIFO world waits for its writer: run, batch, compare, mms exit 143"
mkfifo "$dir/world.txt"
for cmd in run batch compare mms; do
  if [ "$cmd" = mms ]; then
    "$program" mms "$dir/world.txt" -- sh -c 'exit 0' >"$dir/out" 2>"$dir/err" &
  else
    "$program" "$cmd" "$dir/world.txt" >"$dir/out" 2>"$dir/err" &
  fi
  pid=$!
  guard=$(watchdog "$pid" 20)
  wait_opened "$pid" "$dir/world.txt" || fail "$cmd: the world was never opened"
  kill -TERM "$pid"
  status=0
  wait "$pid" || status=$?
  kill "$guard" 2>/dev/null
  [ "$status" = 143 ] || fail "$cmd: exit $status, expected 143"
  cat "$dir/out" "$dir/err" | grep -q "interrupted by SIGTERM" || fail "$cmd: message: $(cat "$dir/err")"
done

begin "a signal after 'wrote DIR/' (the summary held by a full pipe) is exit 143, the output whole"
mkfifo "$dir/stdout"
exec 3<>"$dir/stdout"  # a reader that reads nothing until the signal is sent: the pipe fills
"$program" run "$scratch/maze64.txt" --subcells 5 --quiet --color never --no-trace --no-replay --out "$dir/out" \
  >"$dir/stdout" 2>"$dir/err" 3<&- &
pid=$!
wait_for_text "$dir/err" "^wrote" || fail "no wrote line"
kill -TERM "$pid"
cat "$dir/stdout" 3<&- >"$dir/got" &
reader=$!
status=0
wait "$pid" || status=$?
exec 3<&-
wait "$reader"
[ "$status" = 143 ] || fail "exit $status, expected 143"
[ "$(grep -c "interrupted by SIGTERM" "$dir/err")" = 1 ] || fail "message: $(cat "$dir/err")"
grep -q "^end: " "$dir/got" || fail "the summary was lost"
png_whole "$dir/out/map.png" || fail "map.png cut"
no_temporaries


# `COMMAND | (sleep 100)`: standard output a pipe its reader has filled and never reads, so
# every write waits. SIGTERM once the command waits there ends it (else the watchdog's
# SIGKILL after 60 s): exit 143, said once, no temporary left.
begin "SIGTERM while standard output waits on a full pipe: run, mms, room, plan, compare, batch exit 143"
for cmd in run mms room plan compare batch; do
  rm -f "$dir/stdout"
  mkfifo "$dir/stdout"
  exec 3<>"$dir/stdout"  # the reader that never reads
  dd if=/dev/zero of="$dir/stdout" bs=4096 count=1024 oflag=nonblock 2>/dev/null  # fills the pipe
  case $cmd in
    run) "$program" run "$scratch/maze64.txt" --out "$dir/out-run" >"$dir/stdout" 2>"$dir/err" 3<&- & ;;
    mms) "$program" mms "$scratch/maze64.txt" -- sh -c 'while :; do echo turnLeft; read a; echo moveForward; read a; done' \
      >"$dir/stdout" 2>"$dir/err" 3<&- & ;;
    room) "$program" room worlds/ir_room.room --strategy wander --time-limit 100000 --snapshot-steps 1 \
      >"$dir/stdout" 2>"$dir/err" 3<&- & ;;
    plan) "$program" plan "$lab" >"$dir/stdout" 2>"$dir/err" 3<&- & ;;
    compare) "$program" compare "$lab" >"$dir/stdout" 2>"$dir/err" 3<&- & ;;
    batch) "$program" batch "$lab" --csv "$dir/rows.csv" >"$dir/stdout" 2>"$dir/err" 3<&- & ;;
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
  [ "$(grep -c "interrupted by SIGTERM" "$dir/err")" = 1 ] || fail "$cmd: message: $(cat "$dir/err")"
done
no_temporaries

# $1 signal name, $2 expected status: an mms program that waits, signalled once it started.
signal_in_mms() {
  begin "SIG$1 while mms waits on its program: exit $2, said once, the program ended"
  "$program" mms "$lab" --quiet -- sh -c "echo \$\$ >'$dir/started'; exec sleep 60" >"$dir/out" 2>"$dir/err" &
  pid=$!
  wait_for -s "$dir/started" || fail "the program never started"
  kill -"$1" "$pid"
  status=0
  wait "$pid" || status=$?
  [ "$status" = "$2" ] || fail "exit $status, expected $2"
  grep -qx "end: interrupted by SIG$1" "$dir/out" || fail "end line: $(grep '^end' "$dir/out")"
  ! kill -0 "$(cat "$dir/started")" 2>/dev/null || fail "the program still runs"
}
signal_in_mms TERM 143
signal_in_mms HUP 129

begin "SIGTERM of an mms batch: exit 143, the interrupted row marked and out of the totals"
"$program" batch "$lab" --jobs 1 -- sh -c "echo \$\$ >'$dir/started'; exec sleep 60" >"$dir/out" 2>"$dir/err" &
pid=$!
wait_for -s "$dir/started" || fail "the program never started"
kill -TERM "$pid"
status=0
wait "$pid" || status=$?
[ "$status" = 143 ] || fail "exit $status, expected 143"
grep -q "lab4x4.txt .* interrupted .*interrupted by SIGTERM$" "$dir/out" || fail "row: $(grep lab4x4 "$dir/out")"
grep -q "^total: 1 worlds, 0 ok, 0 failed, 1 interrupted; goal reached 0 of 0; mean score -$" "$dir/out" ||
  fail "totals: $(grep '^total' "$dir/out")"

begin "an mms program's grandchild in a session of its own ends with the run; the program's exit is its end"
"$program" mms "$lab" --quiet --wall-limit 20 -- sh -c "setsid sh -c 'echo \$\$ >\"$dir/grandchild\"; exec sleep 60' &
  while [ ! -s '$dir/grandchild' ]; do sleep 0.01; done; exit 0" >"$dir/out" 2>"$dir/err"
grep -q "^end: exited (the algorithm ended (exit status 0) after 0 lines)" "$dir/out" ||
  fail "end line: $(grep '^end' "$dir/out")"
if kill -0 "$(cat "$dir/grandchild")" 2>/dev/null; then
  fail "the grandchild still runs"
  kill "$(cat "$dir/grandchild")"
fi

# --- The soak: random runs interrupted at random moments (seeded; ~20 s) -----------------

begin "soak: 8 runs of random mazes, each interrupted at a random moment: outputs whole, no temporary"
sh "$source_dir/tests/faults/soak.sh" "$program" 8 "${MAZE_MAPPER_SOAK_SEED:-1}" "$dir" >"$dir/soak.log" 2>&1 ||
  fail "$(cat "$dir/soak.log")"

begin ""
echo "$((count - 1)) fault and signal cases, $failures failed"
[ "$failures" -eq 0 ]
