"""A teacher grading the course's labs from what the students' controllers do and print
(python3 -m maze_mapper.grade --controllers with --goal, --estimate and --keep)."""

import csv
import os
import subprocess
import sys

from conftest import REPO

COURSE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "course_shape")
WORLDS = os.path.join(COURSE, "WebotsSim", "worlds")

# Lab 3: from its start facing the yellow landmark (1.5, 0), drive until 0.5 m short of its
# centre and stop: the body 0.16 m from the cylinder's surface.
REACHES = """from fairis_tools.my_robot import MyRobot
robot = MyRobot()
robot.load_environment(WORLD)
robot.move_to_start()
while robot.experiment_supervisor.step(robot.timestep) != -1:
    if robot.gps.getValues()[0] >= 1.0:
        robot.set_velocities(0, 0)
        break
    robot.set_velocities(10, 10)
robot.experiment_supervisor.step(robot.timestep)
print("stopped near the landmark")
"""
# Lab 4: first a guess in the far corner, then while it drives north 1 m its GPS position
# 0.1 m east of the truth, printed as the lab's position estimate.
ESTIMATES = """from fairis_tools.my_robot import MyRobot
robot = MyRobot()
robot.load_environment(WORLD)
robot.move_to_start()
print("position estimate: x=2.00 y=2.00")
y0, steps = robot.gps.getValues()[1], 0
while robot.experiment_supervisor.step(robot.timestep) != -1:
    x, y, _ = robot.gps.getValues()
    if y - y0 >= 1.0:
        robot.set_velocities(0, 0)
        break
    robot.set_velocities(10, 10)
    steps += 1
    if steps % 16 == 0:
        print(f"position estimate: x={x + 0.1:.3f} y={y:.3f}")
        print("distance to yellow: 2.5")
robot.experiment_supervisor.step(robot.timestep)
x, y, _ = robot.gps.getValues()
print(f"position estimate: x={x + 0.1:.3f} y={y:.3f}")
"""
CRASHES = """from fairis_tools.my_robot import MyRobot
robot = MyRobot()
robot.load_environment(WORLD)
robot.move_to_start()
print("about to look at the landmarks")
robot.get_landmark_distances()
"""
SPINS = """from fairis_tools.my_robot import MyRobot
robot = MyRobot()
robot.load_environment(WORLD)
robot.move_to_start()
while robot.experiment_supervisor.step(robot.timestep) != -1:
    robot.set_velocities(-3, 3)
"""


def hand_in(folder, world, students):
    for student, source in students.items():
        (folder / student).mkdir(parents=True)
        (folder / student / f"{student}.py").write_text(f"WORLD = {os.path.join(WORLDS, world)!r}\n" + source)


def grade(cwd, *args):
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([os.environ.get("PYTHONPATH", ""), COURSE]))
    return subprocess.run([sys.executable, "-m", "maze_mapper.grade", *args], cwd=cwd, capture_output=True,
                          text=True, timeout=600, env=env)


def rows_of(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def test_lab_3_a_landmark_reached_a_crash_and_a_time_out_with_each_run_kept(tmp_path):
    hand_in(tmp_path / "class", "bug0_landmark.xml", {"anna": REACHES, "cal": CRASHES, "dee": SPINS})
    done = grade(tmp_path, "--controllers", "class", "--starts", "2", "--time-limit", "6", "--goal", "yellow",
                 "--goal-distance", "0.3", "--keep", "kept", "--csv", "lab3.csv")
    assert done.returncode == 1, done.stderr
    rows = rows_of(tmp_path / "lab3.csv")
    assert [(r["student"], r["start"], r["result"], r["goal"]) for r in rows] == [
        ("anna", "1", "finished", "reached"), ("anna", "2", "finished", "reached"),
        ("cal", "1", "crashed", "not reached"), ("cal", "2", "crashed", "not reached"),
        ("dee", "1", "timed out", "not reached"), ("dee", "2", "timed out", "not reached")]
    anna = rows[:2]
    assert all(0.1 < float(r["landmark_gap_m"]) < 0.2 for r in anna)
    assert {round(float(r["final_y"]), 1) for r in anna} == {0.1, -0.1}  # the world's two starts, each once
    assert rows[2]["error"] == "AttributeError: 'MyRobot' object has no attribute 'get_landmark_distances'"
    assert {r["end"] for r in rows[4:]} == {"time limit"} and {r["exit"] for r in rows[4:]} == {"0"}
    lines = done.stdout.splitlines()
    assert lines[0].split()[:7] == ["student", "finished", "timed", "out", "crashed", "goal", "reached"]
    assert lines[1].split()[:5] == ["anna", "2/2", "0", "0", "2/2"]
    assert lines[2].split()[:5] == ["cal", "0/2", "0", "2", "0/2"]
    assert lines[2].endswith("own, start 1: crashed: AttributeError: 'MyRobot' object has no attribute "
                             "'get_landmark_distances'")
    assert lines[3].split()[:5] == ["dee", "0/2", "2", "0", "0/2"] and lines[3].endswith("timed out: time limit")
    assert lines[-1] == "total: 6 runs, 2 finished, 2 reached the goal; rows in lab3.csv; runs kept in kept"
    for student in ("anna", "cal", "dee"):
        for start in ("own-1", "own-2"):
            kept = tmp_path / "kept" / student / start
            assert {"summary.json", "trace.csv", "truth.png", "replay.html", "controller.log",
                    "controller_lines.csv"} <= set(os.listdir(kept)), kept
    assert (tmp_path / "kept" / "anna" / "own-1" / "controller.log").read_text() == "stopped near the landmark\n"
    cal_log = (tmp_path / "kept" / "cal" / "own-1" / "controller.log").read_text()
    assert cal_log.startswith("about to look at the landmarks\nTraceback (most recent call last):\n")
    assert cal_log.endswith("AttributeError: 'MyRobot' object has no attribute 'get_landmark_distances'\n")


def test_lab_4_position_estimates_printed_are_compared_with_the_true_pose_of_their_step(tmp_path):
    hand_in(tmp_path / "class", "localization_arena.xml", {"ben": ESTIMATES, "cal": CRASHES, "dee": SPINS})
    done = grade(tmp_path, "--controllers", "class", "--starts", "2", "--time-limit", "5",
                 "--estimate", r"position estimate: x=(\S+) y=(\S+)", "--csv", "lab4.csv")
    assert done.returncode == 1, done.stderr
    assert sorted(os.listdir(tmp_path)) == ["class", "lab4.csv"]  # no run's folder unless --keep
    rows = rows_of(tmp_path / "lab4.csv")
    assert [(r["student"], r["result"]) for r in rows] == [
        ("ben", "finished"), ("ben", "finished"), ("cal", "crashed"), ("cal", "crashed"),
        ("dee", "timed out"), ("dee", "timed out")]
    for r in rows[:2]:
        n = int(r["estimates"])
        assert n >= 5
        assert abs(float(r["estimate_error_m"]) - 0.1) < 0.02  # the last estimate, 0.1 m east of the truth
        assert r["right_cell"] == f"{100.0 * (n - 1) / n:.1f}%"  # all but the first guess
    assert {r["estimates"] for r in rows[2:]} == {"0"}
    lines = done.stdout.splitlines()
    assert lines[0].split()[7:12] == ["last", "estimate", "error", "right", "cell"]
    assert lines[1].split()[:7] == ["ben", "2/2", "0", "0", "-", "0.10", "m"]
    assert lines[-1] == "total: 6 runs, 2 finished, 0 reached the goal; rows in lab4.csv"


def test_cell_estimates_use_the_course_s_numbering_from_the_north_west(tmp_path):
    source = ESTIMATES.replace('print("position estimate: x=2.00 y=2.00")', 'print("I am in cell 5")').replace(
        'print(f"position estimate: x={x + 0.1:.3f} y={y:.3f}")',
        'print(f"I am in cell {int(2.5 - y) * 5 + int(x + 2.5) + 1}")')
    hand_in(tmp_path / "class", "localization_arena.xml", {"ben": source})
    done = grade(tmp_path, "--controllers", "class", "--starts", "2", "--time-limit", "5",
                 "--estimate", r"in cell (?P<cell>\d+)", "--keep", "kept", "--csv", "cells.csv")
    assert done.returncode == 0, done.stderr
    rows = rows_of(tmp_path / "cells.csv")
    log = (tmp_path / "kept" / "ben" / "own-1" / "controller.log").read_text().splitlines()
    # From (-2, -2) (cell 21) 1 m north: cell 16; the last estimate 0.5 m from its cell's centre at most.
    assert log[0] == "I am in cell 5" and log[-1] == "I am in cell 16"
    for r in rows:
        n = int(r["estimates"])
        assert r["right_cell"] == f"{100.0 * (n - 1) / n:.1f}%"
        assert float(r["estimate_error_m"]) < 0.5


def test_help_shows_both_modes_and_no_file_is_written_unasked(tmp_path):
    done = grade(tmp_path, "--help")
    assert done.returncode == 0
    assert "python3 -m maze_mapper.grade WORLD FOLDER|FILE..." in done.stdout
    assert "python3 -m maze_mapper.grade --controllers FOLDER" in done.stdout
    assert "--estimate REGEX" in done.stdout and "--keep DIR" in done.stdout
    hand_in(tmp_path / "class", "bug0_landmark.xml", {"anna": REACHES})
    done = grade(tmp_path, "--controllers", "class", "--time-limit", "6")
    assert done.returncode == 0, done.stderr
    assert sorted(os.listdir(tmp_path)) == ["class"] and sorted(os.listdir(tmp_path / "class" / "anna")) == ["anna.py"]
    done = grade(tmp_path, "--controllers", "class", "--estimate", "(")
    assert done.returncode == 2 and done.stderr.startswith("error: --estimate (: not a regular expression")


def test_shards_merged_print_the_table_and_csv_of_one_run(tmp_path):
    hand_in(tmp_path / "class", "bug0_landmark.xml", {"anna": REACHES, "cal": CRASHES})
    common = ["--controllers", "class", "--starts", "2", "--time-limit", "6", "--goal", "landmark"]
    whole = grade(tmp_path, *common, "--csv", "all.csv")
    assert whole.returncode == 1, whole.stderr
    for k in (1, 2, 3):
        part = grade(tmp_path, *common, "--shard", f"{k}/3", "--csv", f"part-{k}.csv")
        assert part.returncode == (1 if k == 3 else 0), part.stderr  # parts: anna 1 | anna 2 | cal 1, cal 2
    assert [len(rows_of(tmp_path / f"part-{k}.csv")) for k in (1, 2, 3)] == [1, 1, 2]
    (tmp_path / "all.csv").rename(tmp_path / "one.csv")
    merged = grade(tmp_path, "--merge", "part-1.csv", "part-2.csv", "part-3.csv", "--csv", "all.csv")
    assert merged.returncode == 1, merged.stderr
    assert merged.stdout == whole.stdout
    assert (tmp_path / "all.csv").read_text() == (tmp_path / "one.csv").read_text()
    done = grade(tmp_path, *common, "--shard", "4/3", "--csv", "x.csv")
    assert done.returncode == 2 and done.stderr == "error: --shard must be K/N with 1 <= K <= N, e.g. 2/8 (got '4/3')\n"
    done = grade(tmp_path, "--merge", "class/anna/anna.py")
    assert done.returncode == 2 and "not the CSV of a grade --controllers run" in done.stderr
