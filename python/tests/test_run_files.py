"""The files of a Python controller's run (python3 -m maze_mapper.run --out DIR): the same core
files as every run, written by the program's own writers, with the same care for what the
user pointed at."""

import csv
import json
import os
import struct

from conftest import run_controller, summary_of, world

DRIVE = ("from controller import Robot\nimport math\nrobot = Robot()\n"
         "left, right = robot.getDevice('left motor'), robot.getDevice('right motor')\n"
         "for m in (left, right):\n    m.setPosition(math.inf)\n    m.setVelocity(5.0)\n"
         "for _ in range(40):\n    robot.step(32)\n")

KEEP_GRID = ("import maze_mapper\nimport numpy as np\n"
             "grid = np.zeros((4, 4, 3, 3), dtype=np.float32)\ngrid[0, 0, 1, 0] = 1.0\n"
             "maze_mapper.keep_grid(grid, [(0, 0)])\n")

CORE_KEYS = ["world", "model", "strategy", "robot", "seed", "end", "end_message", "steps", "sim_time_s",
             "wall_time_ms"]


def test_a_maze_run_writes_the_core_files_with_the_core_keys_in_order(controller_file, tmp_path):
    out = tmp_path / "out"
    status, stdout, err = run_controller(controller_file(DRIVE + KEEP_GRID), "--world", world("lab4x4.txt"),
                                         "--out", str(out))
    assert status == 0, err
    assert sorted(os.listdir(out)) == ["map.png", "replay.html", "summary.json", "trace.csv", "truth.png"]
    assert f"wrote {out}/: map.png, truth.png, summary.json, trace.csv, replay.html" in err.splitlines()
    summary = json.loads((out / "summary.json").read_text())
    keys = list(summary)
    assert [k for k in keys if k in CORE_KEYS] == CORE_KEYS
    assert summary["model"] is None and summary["strategy"] is None and summary["end_message"] == ""
    assert summary["end"] == "controller finished" and summary["steps"] == 40
    assert summary["goal"] == "not reached"  # lab4x4's goal cell is (3,3)
    printed = summary_of(stdout)
    assert printed["steps"] == "40" and printed["coverage"] == f"{summary['coverage']:.2f}%"
    with open(out / "trace.csv") as f:
        rows = list(csv.reader(f))
    assert rows[0] == ["step", "time_s", "true_x_m", "true_y_m", "true_yaw_rad"]
    assert [r[0] for r in rows[1:3]] == ["1", "2"] and len(rows) == 41
    x, y, _ = summary_of(stdout)["final_pose"].split()
    assert rows[-1][1] == "1.280" and abs(float(rows[-1][2]) - float(x)) < 6e-4 and abs(float(rows[-1][3]) - float(y)) < 6e-4
    assert (out / "truth.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert b'id="replay-data"' in (out / "replay.html").read_bytes()


def test_an_arena_run_writes_the_summary_the_trace_and_a_truth_picture_of_its_solids_and_path(controller_file, tmp_path):
    out = tmp_path / "out"
    status, _, err = run_controller(controller_file(DRIVE), "--world", world("thick_arena.xml"), "--out", str(out))
    assert status == 0, err
    assert sorted(os.listdir(out)) == ["summary.json", "trace.csv", "truth.png"]
    png = (out / "truth.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", png[16:24])
    assert width >= 400 and height >= 400  # 400 cells on the arena's longer side, and the legend
    summary = json.loads((out / "summary.json").read_text())
    assert summary["arena"] and summary["goal"] == "not reached" and summary["steps"] == 40


def test_a_dangling_link_as_out_is_refused_and_left(controller_file, tmp_path):
    link = tmp_path / "out"
    link.symlink_to(tmp_path / "nowhere")
    status, stdout, err = run_controller(controller_file(DRIVE), "--world", world("lab4x4.txt"), "--out", str(link))
    assert status == 2 and stdout == ""
    assert err.startswith(f"error: --out {link}:")
    assert link.is_symlink() and not (tmp_path / "nowhere").exists()


def test_an_input_inside_out_under_an_output_s_name_is_refused_before_the_run(controller_file, tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    kept = out / "trace.csv"
    kept.write_text(open(world("lab4x4.txt")).read())
    before = kept.read_text()
    status, stdout, err = run_controller(controller_file(DRIVE), "--world", str(kept), "--out", str(out))
    assert status == 2 and stdout == ""
    assert err == f"error: --out {out}/trace.csv is also an input (the world {kept}): refusing to overwrite it\n"
    assert kept.read_text() == before and os.listdir(out) == ["trace.csv"]


def test_a_second_run_into_the_same_out_leaves_only_its_own_files(controller_file, tmp_path):
    out = tmp_path / "out"
    status, _, err = run_controller(controller_file(DRIVE + KEEP_GRID), "--world", world("lab4x4.txt"),
                                    "--out", str(out))
    assert status == 0, err
    (out / "notes.txt").write_text("mine")
    status, _, err = run_controller(controller_file(DRIVE, name="second.py"), "--world", world("thick_arena.xml"),
                                    "--out", str(out))
    assert status == 0, err
    assert sorted(os.listdir(out)) == ["notes.txt", "summary.json", "trace.csv", "truth.png"]
