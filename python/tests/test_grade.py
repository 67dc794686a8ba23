"""A teacher's grading of a folder of students' grids (python3 -m maze_mapper.grade)."""

import csv
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


def test_a_class_of_controllers_is_one_row_a_student_world_and_start(tmp_path):
    import os
    course = os.path.join(os.path.dirname(os.path.abspath(__file__)), "course_shape")
    drive = os.path.join(course, "WebotsSim", "controllers", "drive", "drive.py")
    source = open(drive).read().replace("'../../worlds/corners.xml'",
                                        repr(os.path.join(course, "WebotsSim", "worlds", "corners.xml")))
    (tmp_path / "class" / "alice").mkdir(parents=True)
    (tmp_path / "class" / "alice" / "lab.py").write_text(source)
    (tmp_path / "class" / "bob").mkdir()
    (tmp_path / "class" / "bob" / "bob.py").write_text("from controller import Robot\nraise RuntimeError('lost')\n")
    (tmp_path / "class" / "bob" / "helpers.py").write_text("")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([os.environ.get("PYTHONPATH", ""), course]))
    done = subprocess.run([sys.executable, "-m", "maze_mapper.grade", "--controllers", str(tmp_path / "class"),
                           "--starts", "2", "--csv", str(tmp_path / "runs.csv")],
                          cwd=REPO, capture_output=True, text=True, timeout=300, env=env)
    assert done.returncode == 0, done.stderr
    rows = list(csv.DictReader(open(tmp_path / "runs.csv")))
    assert [(r["student"], r["world"], r["start"], r["exit"]) for r in rows] == [
        ("alice", "own", "1", "0"), ("alice", "own", "2", "0"), ("bob", "own", "1", "1"), ("bob", "own", "2", "1")]
    assert rows[0]["end"] == "controller finished" and 1.49 < float(rows[0]["distance_m"]) < 1.52
    assert rows[0]["collisions"] == "0"
    assert rows[2]["error"] == "RuntimeError: lost"
    lines = done.stdout.splitlines()
    assert lines[0].startswith("alice: 2/2 runs finished, mean 2.0 s simulated")
    assert lines[1] == "bob: 0/2 runs finished; first failure (own, start 1): RuntimeError: lost"
