"""How a run of python3 -m maze_mapper.run ends, as carefully as the program's commands end:
stop signals, a controller that forks, exit codes no status holds, exceptions that are not
Exceptions, a full disk."""

import json
import os
import shutil
import signal
import subprocess
import sys

import pytest

from conftest import REPO, run_controller, summary_of, temporaries_under, world

STEP_ON = ("from controller import Robot\nimport math, sys\nrobot = Robot()\n"
           "left, right = robot.getDevice('left motor'), robot.getDevice('right motor')\n"
           "for m in (left, right):\n    m.setPosition(math.inf)\n    m.setVelocity(2.0)\n"
           "robot.step(32)\nprint('stepping', flush=True)\n")


def assert_whole(out):
    """Every file of --out DIR whole: trace.csv one header and whole rows, summary.json JSON."""
    trace = (out / "trace.csv").read_text()
    assert trace.endswith("\n") and trace.count("step,") == 1
    json.loads((out / "summary.json").read_text())
    # after a stop signal the pictures get 2 s, summary.json and trace.csv first: whole if written
    assert not (out / "truth.png").exists() or (out / "truth.png").read_bytes().endswith(b"IEND\xaeB`\x82")
    assert temporaries_under(out) == []


def signalled(controller, signal_number, *args):
    """Runs the controller until it prints `stepping`, sends it the signal; (status, stdout, stderr)."""
    process = subprocess.Popen([sys.executable, "-m", "maze_mapper.run", str(controller), *args], cwd=REPO,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    first = process.stdout.readline()
    assert first == "stepping\n", first + process.stderr.read()
    process.send_signal(signal_number)
    stdout, stderr = process.communicate(timeout=60)
    return process.returncode, first + stdout, stderr


@pytest.mark.parametrize("signal_number, status, name", [(signal.SIGTERM, 143, "SIGTERM"), (signal.SIGHUP, 129, "SIGHUP"),
                                                       (signal.SIGINT, 130, "Ctrl-C")])
def test_a_stop_signal_ends_the_run_at_its_next_step_with_the_summary_and_whole_files(
        controller_file, tmp_path, signal_number, status, name):
    controller = controller_file(STEP_ON + "while robot.step(32) != -1:\n    pass\nprint('left the loop')\n")
    out = tmp_path / "out"
    got, stdout, err = signalled(controller, signal_number, "--world", world("maze8x8.txt"),
                                 "--max-steps", "10000000", "--out", str(out))
    assert got == status, err
    assert "left the loop" in stdout.splitlines()
    assert summary_of(stdout)["end"] == f"stopped (interrupted by {name})"
    summary = json.loads((out / "summary.json").read_text())
    assert summary["end"] == "stopped" and summary["end_message"] == f"interrupted by {name}"
    assert "Traceback" not in err
    assert_whole(out)


def test_a_controller_that_stops_stepping_is_interrupted_after_a_signal_and_the_run_still_summarised(
        controller_file, tmp_path):
    controller = controller_file(STEP_ON + "while True:\n    pass\n")
    out = tmp_path / "out"
    got, stdout, err = signalled(controller, signal.SIGTERM, "--world", world("maze8x8.txt"), "--out", str(out))
    assert got == 143, err
    assert summary_of(stdout)["end"] == "stopped (interrupted by SIGTERM)"
    assert_whole(out)


FORKS = ("import os\n"
         "for _ in range(5):\n    robot.step(32)\n"
         "pid = os.fork()\n"
         "if pid == 0:\n"
         "    print('child steps', robot.step(32), flush=True)\n"
         "else:\n"
         "    os.waitpid(pid, 0)\n"
         "    for _ in range(10):\n        robot.step(32)\n")


def test_a_child_the_controller_forks_neither_steps_the_run_nor_ends_it_nor_writes_its_files(controller_file, tmp_path):
    out = tmp_path / "out"
    status, stdout, err = run_controller(controller_file(STEP_ON + FORKS), "--world", world("maze8x8.txt"),
                                         "--out", str(out))
    assert status == 0, err
    assert "child steps -1" in stdout.splitlines()
    assert stdout.count("\nend: ") == 1 and err.count("wrote ") == 1
    rows = (out / "trace.csv").read_text().splitlines()
    assert rows[0].startswith("step,") and [r.split(",")[0] for r in rows[1:]] == [str(k) for k in range(1, 17)]
    assert summary_of(stdout)["steps"] == "16"
    assert_whole(out)


@pytest.mark.parametrize("code", [256, 512, 2 ** 31, -1])
def test_an_exit_code_no_exit_status_holds_is_a_failed_controller_with_status_1(controller_file, code):
    status, stdout, err = run_controller(controller_file(STEP_ON + f"sys.exit({code})\n"), "--world",
                                         world("lab4x4.txt"))
    assert status == 1, err
    assert summary_of(stdout)["end"] == "controller failed"


@pytest.mark.parametrize("raised", ["class Stop(BaseException):\n    pass\nraise Stop('enough')\n",
                                    "raise GeneratorExit('enough')\n",
                                    "raise KeyboardInterrupt('enough')\n"])  # its own, no signal: no interruption
def test_a_base_exception_from_the_controller_is_a_failed_controller_with_its_traceback_summary_and_files(
        controller_file, tmp_path, raised):
    out = tmp_path / "out"
    status, stdout, err = run_controller(controller_file(STEP_ON + raised), "--world", world("lab4x4.txt"),
                                         "--out", str(out))
    assert status == 1, err
    assert "Traceback" in err and err.count(": enough") == 1
    assert summary_of(stdout)["end"] == "controller failed"
    assert_whole(out)


def in_tiny_disk(tmp_path, *args, size="16k"):
    """Runs the runner with `tmp_path/tiny` a tmpfs of `size` in a mount namespace of its own;
    (status, stdout, stderr). Skips where mounting is not allowed."""
    tiny = tmp_path / "tiny"
    tiny.mkdir()
    if not shutil.which("unshare") or subprocess.run(
            ["unshare", "-m", "sh", "-c", f"mount -t tmpfs -o size={size} tmpfs '{tiny}'"],
            capture_output=True).returncode != 0:
        pytest.skip("mounting a tmpfs is not allowed here")
    script = f"mount -t tmpfs -o size={size} tmpfs '{tiny}' && exec \"$@\""
    done = subprocess.run(["unshare", "-m", "sh", "-c", script, "sh", sys.executable, "-m", "maze_mapper.run", *args],
                          cwd=REPO, capture_output=True, text=True, timeout=300)
    return done.returncode, done.stdout, done.stderr


def test_a_full_disk_when_the_files_are_written_is_one_error_line_after_the_summary_and_status_4(
        controller_file, tmp_path):
    controller = controller_file(STEP_ON + "for _ in range(3000):\n    robot.step(32)\n")
    status, stdout, err = in_tiny_disk(tmp_path, str(controller), "--world", world("maze8x8.txt"),
                                       "--out", str(tmp_path / "tiny" / "out"))
    assert status == 4, err
    assert summary_of(stdout)["end"] == "controller finished"
    assert err.count("error: ") == 1 and "Traceback" not in err
    assert [line for line in err.splitlines() if "error" in line][0].endswith(": No space left on device")


def test_a_disk_that_fills_during_the_run_is_not_blamed_on_the_controller_and_is_status_4(controller_file, tmp_path):
    # 40,000 rows of trace.csv (about 1.2 MB) go out in 1 MiB pieces: the first one meets the full disk.
    controller = controller_file(STEP_ON + "for _ in range(40000):\n    robot.step(32)\nprint('done', flush=True)\n")
    status, stdout, err = in_tiny_disk(tmp_path, str(controller), "--world", world("maze8x8.txt"),
                                       "--out", str(tmp_path / "tiny" / "out"))
    assert status == 4, err
    assert "done" in stdout.splitlines()
    assert summary_of(stdout)["end"] == "controller finished"
    assert err.count("error: ") == 1 and "Traceback" not in err
    assert f"error: cannot write {tmp_path}/tiny/out/trace.csv: No space left on device" in err.splitlines()


QUIET = "from controller import Robot\nrobot = Robot()\nfor _ in range(5):\n    robot.step(32)\n"


def test_standard_output_on_a_full_device_is_one_error_line_and_status_4_with_the_files_written(
        controller_file, tmp_path):
    out = tmp_path / "out"
    with open("/dev/full", "w") as full:
        done = subprocess.run([sys.executable, "-m", "maze_mapper.run", str(controller_file(QUIET)),
                               "--world", world("lab4x4.txt"), "--out", str(out)],
                              cwd=REPO, stdout=full, stderr=subprocess.PIPE, text=True, timeout=300)
    assert done.returncode == 4, done.stderr
    assert [line for line in done.stderr.splitlines() if not line.startswith("wrote ")] == [
        "error: cannot write standard output: No space left on device"]
    assert_whole(out)


@pytest.mark.parametrize("closed", ["stdout", "stderr"])
def test_a_closed_standard_stream_takes_no_file_of_the_run(controller_file, tmp_path, closed):
    """`python3 -m maze_mapper.run C.py --out d >&-`: the trace does not become fd 1 and take
    the printed summary; with stderr closed the run still ends with its status."""
    controller = controller_file(STEP_ON + "for _ in range(20):\n    robot.step(32)\n")
    out = tmp_path / "out"
    command = [sys.executable, "-m", "maze_mapper.run", str(controller), "--world", world("maze8x8.txt"),
               "--out", str(out)]
    fd = 1 if closed == "stdout" else 2
    done = subprocess.run(command, cwd=REPO, pass_fds=(), preexec_fn=lambda: os.close(fd),
                          stdout=subprocess.DEVNULL if fd == 2 else None, stderr=subprocess.DEVNULL if fd == 1 else None)
    assert done.returncode == 0
    trace = (out / "trace.csv").read_text()
    assert trace.startswith("step,") and trace.count("step,") == 1 and "end:" not in trace
    json.loads((out / "summary.json").read_text())
    assert temporaries_under(out) == []
