#!/bin/sh
# A class graded on a real scheduler: a one-node Slurm (slurmctld + slurmd, munge for its
# authentication; all three started here, in a scratch folder, on free ports, and stopped at
# the end) runs docs/grading.md's job-array script, four tasks of
# `grade --controllers ... --shard K/4`; `grade --merge` of the four parts must print the
# table and write the CSV a one-machine run does, row for row. Then docs/grading.md's GNU
# parallel line, the same again. The script and the line are taken from docs/grading.md, so
# the docs run as they read.
# Needs root and Debian's slurmctld, slurmd, slurm-client, munge and parallel
# (scripts/install-test-deps.sh); skips (exit 77) without them, unless MAZE_MAPPER_REQUIRE_SLURM
# is set. Usage: slurm_grade.sh PYTHON SOURCE_DIR   (PYTHONPATH on the module)
set -eu
python=$1
source_dir=$2
docs="$source_dir/docs/grading.md"

missing=""
for tool in slurmctld slurmd sbatch scontrol munged parallel; do
    command -v "$tool" >/dev/null 2>&1 || missing="$missing $tool"
done
if [ -n "$missing" ] || [ "$(id -u)" != 0 ]; then
    echo "skipped: needs root and$missing (scripts/install-test-deps.sh)" >&2
    [ -n "${MAZE_MAPPER_REQUIRE_SLURM:-}" ] && exit 1
    exit 77
fi

work=$(mktemp -d /tmp/maze_mapper_slurm.XXXXXX)
stop_daemons() {
    if [ -f "$work/slurm.conf" ]; then
        SLURM_CONF="$work/slurm.conf" scontrol shutdown >/dev/null 2>&1 || true
        for pidfile in "$work/slurmctld.pid" "$work/slurmd.pid"; do
            # scontrol shutdown ends both; a daemon left after 10 s is ended by its own pid.
            for _ in 1 2 3 4 5 6 7 8 9 10; do
                [ -f "$pidfile" ] && kill -0 "$(cat "$pidfile")" 2>/dev/null || break
                sleep 1
            done
            [ -f "$pidfile" ] && kill "$(cat "$pidfile")" 2>/dev/null || true
        done
    fi
    [ -S "$work/munge.sock" ] && munged -s --socket="$work/munge.sock" >/dev/null 2>&1 || true
}
cleanup() {
    status=$?
    stop_daemons
    if [ $status -ne 0 ]; then
        for log in "$work"/*.log "$work"/run/grade-*.out; do
            [ -f "$log" ] && { echo "--- $log"; tail -n 20 "$log"; } >&2
        done
    fi
    rm -rf "$work"
    exit $status
}
trap cleanup EXIT
trap 'exit 130' INT TERM HUP
fail() { echo "FAIL: $*" >&2; exit 1; }
# The docs' `python3` is the interpreter the module is built for, here and in Slurm's tasks
# (which inherit this environment, PYTHONPATH too).
mkdir "$work/bin"
ln -s "$(command -v "$python")" "$work/bin/python3"
PATH="$work/bin:$PATH"
export PATH

# The class: anna drives to the yellow landmark and stops short of it; bob's controller
# raises; carol stops halfway; dave handed in no controller.
class="$work/class"
mkdir -p "$class/anna" "$class/bob" "$class/carol" "$class/dave"
drive_to() {  # drive_to X: a controller driving east until its GPS says X
    cat <<PY
from controller import Robot
robot = Robot()
gps = robot.getDevice('gps')
gps.enable(32)
left, right = robot.getDevice('left motor'), robot.getDevice('right motor')
for m in (left, right):
    m.setPosition(float('inf'))
while robot.step(32) != -1:
    if gps.getValues()[0] >= $1:
        break
    for m in (left, right):
        m.setVelocity(10.0)
for m in (left, right):
    m.setVelocity(0.0)
robot.step(32)
print('stopped at', round(gps.getValues()[0], 2))
PY
}
drive_to 1.0 > "$class/anna/anna.py"
printf 'raise RuntimeError("lost")\n' > "$class/bob/bob.py"
drive_to 0.0 > "$class/carol/carol.py"
printf 'notes\n' > "$class/dave/notes.txt"

# Each way runs in a folder of its own holding class/ and lab3.xml, as the docs' commands expect.
prepare() {
    mkdir -p "$1"
    ln -s "$class" "$1/class"
    cp "$source_dir/python/tests/course_shape/WebotsSim/worlds/bug0_landmark.xml" "$1/lab3.xml"
}

# The one-machine run.
prepare "$work/one"
(cd "$work/one" && python3 -m maze_mapper.grade --controllers class/ --world lab3.xml --starts 2 \
    --goal yellow --csv lab3.csv > table.txt 2> errors.txt) && fail "the class's run exited 0 (bob's and dave's runs failed)"
grep -q '^anna .* 2/2' "$work/one/table.txt" || fail "anna did not reach the landmark: $(cat "$work/one/table.txt")"

# Slurm: munge, then the controller and the node, from a configuration of our own.
key="$work/munge.key"
dd if=/dev/urandom of="$key" bs=1024 count=1 2>/dev/null
chmod 600 "$key"
munged -f --socket="$work/munge.sock" --key-file="$key" --log-file="$work/munged.log" \
    --pid-file="$work/munged.pid" --seed-file="$work/munged.seed"
ports=$(python3 -c 'import socket
for _ in range(2):
    s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()')
node=$(hostname -s)
node_line=$(slurmd -C | head -n 1 | sed 's/RealMemory=[0-9]*/RealMemory=500/')
mkdir -p "$work/state" "$work/spool"
cat > "$work/slurm.conf" <<CONF
ClusterName=maze_mapper_test
SlurmctldHost=$node
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge.sock
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldPort=$(echo "$ports" | sed -n 1p)
SlurmdPort=$(echo "$ports" | sed -n 2p)
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
SwitchType=switch/none
$node_line State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$work/slurm.conf"
slurmctld -i
slurmd
for _ in $(seq 30); do
    sinfo -h -o %t 2>/dev/null | grep -q idle && break
    sleep 1
done
sinfo -h -o %t | grep -q idle || fail "the Slurm node did not come up: $(sinfo 2>&1)"

# The docs' job-array script, run as they say (sbatch --wait; a task whose runs failed ends
# FAILED, so sbatch's own status is not the test's), then the merge.
prepare "$work/run"
awk '/^```sh$/ { block = ""; inside = 1; next } /^```$/ { if (inside && block ~ /^#!\/bin\/sh\n#SBATCH/) { printf "%s", block; exit } inside = 0; next }
     inside { block = block $0 "\n" }' "$docs" > "$work/run/grade.sh"
grep -q -- '--shard "$SLURM_ARRAY_TASK_ID/4"' "$work/run/grade.sh" || fail "no job-array script in $docs"
(cd "$work/run" && sbatch --wait grade.sh > sbatch.txt 2>&1) || true
for k in 1 2 3 4; do
    [ -s "$work/run/part-$k.csv" ] || fail "task $k wrote no part-$k.csv: $(cat "$work/run/sbatch.txt")"
done
merge=$(sed -n 's/^\(python3 -m maze_mapper.grade --merge .*\)$/\1/p' "$docs" | head -n 1)
[ -n "$merge" ] || fail "no --merge line in $docs"
(cd "$work/run" && sh -c "$merge" > table.txt 2> errors.txt) && fail "the merge exited 0"
diff "$work/one/table.txt" "$work/run/table.txt" >&2 || fail "Slurm's merged table differs from the one-machine run's"
diff "$work/one/lab3.csv" "$work/run/lab3.csv" >&2 || fail "Slurm's merged CSV differs from the one-machine run's"
stop_daemons

# The docs' GNU parallel line, then the same merge.
prepare "$work/parallel"
line=$(sed -n 's/^\(parallel python3 -m maze_mapper.grade .*\)$/\1/p' "$docs" | head -n 1)
[ -n "$line" ] || fail "no GNU parallel line in $docs"
(cd "$work/parallel" && sh -c "$line" > parallel.txt 2>&1) || true
(cd "$work/parallel" && sh -c "$merge" > table.txt 2> errors.txt) && fail "the merge exited 0"
diff "$work/one/table.txt" "$work/parallel/table.txt" >&2 || fail "parallel's merged table differs from the one-machine run's"
diff "$work/one/lab3.csv" "$work/parallel/lab3.csv" >&2 || fail "parallel's merged CSV differs from the one-machine run's"
echo "Slurm (4 tasks) and GNU parallel: merged tables and CSVs equal the one-machine run's"
cat "$work/one/table.txt"
