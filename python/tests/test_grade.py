"""A teacher's grading of a folder of students' grids (python3 -m maze_mapper.grade)."""

import csv
import os
import subprocess
import sys

import numpy as np

import maze_mapper
from conftest import REPO, world


def grade(*args):
    done = subprocess.run([sys.executable, "-m", "maze_mapper.grade", *args], cwd=REPO,
                          capture_output=True, text=True, timeout=120)
    return done.returncode, done.stdout, done.stderr


def test_a_folder_of_grids_is_one_row_a_file(tmp_path):
    w = maze_mapper.load_world(world("lab4x4.txt"))
    grid, _ = maze_mapper.explore_world(w)
    visited = np.array([[x, y] for y in range(4) for x in range(4) if grid.visited(x, y)])
    np.savez(tmp_path / "alice.npz", grid=grid.array, visited=visited)
    wrong = grid.array.copy()
    wrong[0, 0, 1, 0] = -1.0  # (0,0)'s west wall missed
    np.save(tmp_path / "bob.npy", wrong)
    np.save(tmp_path / "carol.npy", np.zeros((4, 3, 3, 3)))
    (tmp_path / "dave.npz").write_text("not numpy")
    (tmp_path / "notes.txt").write_text("ignored")
    status, out, err = grade("worlds/lab4x4.txt", str(tmp_path), "--csv", str(tmp_path / "grades.csv"))
    assert status == 1, err
    lines = out.splitlines()
    assert lines[1].split()[:4] == [str(tmp_path / "alice.npz"), "100.00%", "100.00%", "0"]
    assert lines[2].split()[:5] == [str(tmp_path / "bob.npy"), "0.00%", "97.50%", "1", "W"]
    assert lines[2].endswith("W of (0,0) a wall missed")
    assert lines[3].endswith(f"{tmp_path / 'carol.npy'}: error: the grid is 3x4 cells, the world 4x4")
    assert f"{tmp_path / 'dave.npz'}: error: cannot read it as a NumPy file" in lines[4]
    assert lines[5] == "total: 4 grids, 2 graded, 2 failed"
    with open(tmp_path / "grades.csv") as f:
        rows = list(csv.DictReader(f))
    assert [r["wall_accuracy"] for r in rows] == ["100.00%", "97.50%", "", ""]


def test_bad_usage():
    status, out, err = grade("worlds/no_such.txt", ".")
    assert status == 2 and out == "" and err.startswith("error: cannot read worlds/no_such.txt")
    status, out, err = grade("worlds/lab4x4.txt", "worlds")
    assert status == 2 and err == "error: no .npz or .npy files in worlds\n"


COURSE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "course_shape")
WORLDS = os.path.join(COURSE, "WebotsSim", "worlds")

# Hand-ins: alice drives ahead 1.43 m at 18 rad/s and saves her grid (a wall west of cell (0,0))
# where her controller runs; bob's controller raises; carol spins in place and steps on past
# the time limit.
ALICE = """from controller import Robot
import math
import numpy as np
robot = Robot()
motors = [robot.getDevice('left motor'), robot.getDevice('right motor')]
for m in motors:
    m.setPosition(math.inf)
    m.setVelocity(18.0)
for _ in range(55):
    robot.step(32)
for m in motors:
    m.setVelocity(0.0)
robot.step(32)
grid = np.zeros((4, 4, 3, 3))
grid[0, 0, 1, 0] = 1.0
np.save('grid.npy', grid)
"""
CAROL = """from controller import Robot
import math
robot = Robot()
left, right = robot.getDevice('left motor'), robot.getDevice('right motor')
for m, v in ((left, -3.0), (right, 3.0)):
    m.setPosition(math.inf)
    m.setVelocity(v)
while True:  # never looks at step's -1
    robot.step(32)
"""


def test_a_class_of_students_runs_over_worlds_and_starts_with_goal_and_map_columns_and_a_table(tmp_path):
    hand_ins = tmp_path / "class"
    for student, name, source in (("alice", "lab.py", ALICE), ("bob", "bob.py", "raise RuntimeError('lost')\n"),
                                  ("carol", "carol.py", CAROL)):
        (hand_ins / student).mkdir(parents=True)
        (hand_ins / student / name).write_text(source)
    (hand_ins / "bob" / "helpers.py").write_text("")
    maze, arena = os.path.join(WORLDS, "lattice_maze.xml"), os.path.join(REPO, "worlds", "thick_arena.xml")
    done = subprocess.run([sys.executable, "-m", "maze_mapper.grade", "--controllers", str(hand_ins),
                           "--world", maze, "--world", arena, "--starts", "2", "--time-limit", "2",
                           "--csv", str(tmp_path / "runs.csv")],
                          cwd=REPO, capture_output=True, text=True, timeout=300)
    assert done.returncode == 1, done.stderr  # runs failed
    rows = list(csv.DictReader(open(tmp_path / "runs.csv")))
    assert [(r["student"], os.path.basename(r["world"]), r["start"], r["exit"]) for r in rows] == [
        (s, w, n, e) for s, e in (("alice", "0"), ("bob", "1"), ("carol", "0"))
        for w in ("lattice_maze.xml", "thick_arena.xml") for n in ("1", "2")]
    alice = rows[:4]
    assert [r["goal"] for r in alice] == ["not reached", "reached", "not reached", "not reached"]
    assert [r["grid"] for r in alice] == ["grid.npy", "grid.npy", "", ""]  # the arena has no lattice to score on
    assert alice[0]["coverage"] == "0.00%" and alice[0]["wall_accuracy"] != ""  # a bare .npy names no visited cell
    assert 0.6 < float(alice[1]["final_y"]) < 0.75  # from (0.75, -0.75) into the goal cell (3,3)
    assert rows[4]["error"] == "RuntimeError: lost"
    carol = rows[8:]
    assert {r["end"] for r in carol} == {"time limit"} and {r["sim_time_s"] for r in carol} == {"2.016"}
    assert [r["result"] for r in rows] == ["finished"] * 4 + ["crashed"] * 4 + ["timed out"] * 4
    lines = done.stdout.splitlines()
    assert lines[0].split() == ["student", "finished", "timed", "out", "crashed", "goal", "reached", "mean", "time",
                                "coverage", "wall", "accuracy", "collisions", "first", "failure"]
    assert lines[1].split()[:6] == ["alice", "4/4", "0", "0", "1/4", "1.8"]
    assert lines[2].split()[:5] == ["bob", "0/4", "0", "4", "0/4"]
    assert lines[2].endswith(f"{maze}, start 1: crashed: RuntimeError: lost")
    assert lines[3].split()[:6] == ["carol", "0/4", "4", "0", "0/4", "-"]
    assert lines[-1] == f"total: 12 runs, 4 finished, 1 reached the goal; rows in {tmp_path / 'runs.csv'}"


def test_a_class_on_the_course_s_own_worlds_draws_the_random_start_from_the_seed(tmp_path):
    drive = os.path.join(COURSE, "WebotsSim", "controllers", "drive", "drive.py")
    source = open(drive).read().replace("'../../worlds/corners.xml'", repr(os.path.join(WORLDS, "corners.xml")))
    (tmp_path / "class" / "alice").mkdir(parents=True)
    (tmp_path / "class" / "alice" / "lab.py").write_text(source)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([os.environ.get("PYTHONPATH", ""), COURSE]))
    done = subprocess.run([sys.executable, "-m", "maze_mapper.grade", "--controllers", str(tmp_path / "class"),
                           "--starts", "2", "--csv", str(tmp_path / "runs.csv")],
                          cwd=REPO, capture_output=True, text=True, timeout=300, env=env)
    assert done.returncode == 0, done.stderr
    rows = list(csv.DictReader(open(tmp_path / "runs.csv")))
    assert [(r["student"], r["world"], r["start"], r["exit"]) for r in rows] == [
        ("alice", "own", "1", "0"), ("alice", "own", "2", "0")]
    # corners.xml's two starts, each once: (-0.75, -1) heading east, (0.75, -0.5) heading west.
    assert [(round(float(r["final_x"]), 1), round(float(r["final_y"]), 1)) for r in rows] == [(0.8, -1.0),
                                                                                                (-0.8, -0.5)]
    assert rows[0]["end"] == "controller finished" and 1.49 < float(rows[0]["distance_m"]) < 1.52
    assert {r["goal"] for r in rows} == {"not reached"}  # corners.xml's goal (1.5, 0), as the library read it


KEY_PRINTER = """from controller import Robot
robot = Robot()
keyboard = robot.getKeyboard()
keyboard.enable(32)
for _ in range(40):
    robot.step(32)
    key = keyboard.getKey()
    if key != -1:
        print(f"key {robot.getTime():.3f} {key}")
"""


def test_keys_hands_its_script_of_timed_keys_to_every_run_and_a_bad_script_is_a_usage_error(tmp_path):
    hand_ins = tmp_path / "class"
    for student in ("alice", "bob"):
        (hand_ins / student).mkdir(parents=True)
        (hand_ins / student / f"{student}.py").write_text(KEY_PRINTER)
    keys = tmp_path / "drive.keys"
    keys.write_text("0.5 UP\n0.6 -\n")
    command = [sys.executable, "-m", "maze_mapper.grade", "--controllers", str(hand_ins),
               "--world", os.path.join(WORLDS, "lattice_maze.xml"), "--keep", str(tmp_path / "runs")]
    done = subprocess.run(command + ["--keys", os.path.relpath(keys, REPO)], cwd=REPO, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    for student in ("alice", "bob"):
        log = (tmp_path / "runs" / student / "lattice_maze-1" / "controller.log").read_text()
        # UP (315) held from 0.5 s to 0.6 s: the samples at 0.512 s and 0.544 s, 0.576 s
        assert [line for line in log.splitlines() if line.startswith("key ")] == [
            "key 0.512 315", "key 0.544 315", "key 0.576 315"], log
    command[command.index("--keep") + 1] = str(tmp_path / "plain")
    without = subprocess.run(command, cwd=REPO, capture_output=True, text=True, timeout=300)
    assert without.returncode == 0, without.stderr
    log = (tmp_path / "plain" / "alice" / "lattice_maze-1" / "controller.log").read_text()
    assert "key " not in log  # no script, no terminal: getKey() returns -1
    keys.write_text("0.5 UP\n0.2 -\n")
    bad = subprocess.run(command + ["--keys", str(keys)], cwd=REPO, capture_output=True, text=True, timeout=60)
    assert bad.returncode == 2 and bad.stderr.startswith(f"{keys}:2:") and bad.stderr.count("\n") == 1, bad.stderr
    assert bad.stdout == ""
