"""The files of a Python controller's run (python3 -m maze_mapper.run --out DIR): the same core
files as every run, written by the program's own writers, with the same care for what the
user pointed at."""

import csv
import json
import os
import struct

from conftest import png_pixels, run_controller, summary_of, world

DRIVE = ("from controller import Robot\nimport math\nrobot = Robot()\n"
         "left, right = robot.getDevice('left motor'), robot.getDevice('right motor')\n"
         "for m in (left, right):\n    m.setPosition(math.inf)\n    m.setVelocity(5.0)\n"
         "for _ in range(40):\n    robot.step(32)\n")

KEEP_GRID = ("import maze_mapper\nimport numpy as np\n"
             "grid = np.zeros((4, 4, 3, 3), dtype=np.float32)\ngrid[0, 0, 1, 0] = 1.0\n"
             "maze_mapper.keep_grid(grid, [(0, 0)])\n")

# A map over thick_arena's 17 x 17 m floor in 0.5 m cells, kept before the loop and changed in
# place each step (the south row occupied, the start's cells free, one more cell of a column a
# step), its north-east cell set after the last step.
KEEP_MAP_DRIVE = ("from controller import Robot\nimport math\nimport numpy as np\nimport maze_mapper\n"
                  "grid = np.zeros((34, 34))\n"
                  "maze_mapper.keep_map(grid, origin=(-8.5, -8.5), cell_size_m=0.5)\n"
                  "robot = Robot()\n"
                  "left, right = robot.getDevice('left motor'), robot.getDevice('right motor')\n"
                  "for m in (left, right):\n    m.setPosition(math.inf)\n    m.setVelocity(5.0)\n"
                  "for k in range(40):\n    robot.step(32)\n"
                  "    grid[0, :] += 0.41\n    grid[2:5, 2:5] -= 0.85\n    grid[k % 34, 20] = 2.0\n"
                  "grid[33, 33] = 3.0\n")

CORE_KEYS = ["world", "model", "strategy", "robot", "seed", "end", "end_message", "steps", "sim_time_s",
             "wall_time_ms"]


def test_a_maze_run_writes_the_core_files_with_the_core_keys_in_order(controller_file, tmp_path):
    out = tmp_path / "out"
    status, stdout, err = run_controller(controller_file(DRIVE + KEEP_GRID), "--world", world("lab4x4.txt"),
                                         "--out", str(out))
    assert status == 0, err
    assert sorted(os.listdir(out)) == ["controller.log", "controller_lines.csv", "map.png", "replay.html", "summary.json", "trace.csv", "truth.png"]
    assert f"wrote {out}/: map.png, truth.png, summary.json, trace.csv, replay.html, controller.log, controller_lines.csv" in err.splitlines()
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


def replay_data(page):
    """The data block of a replay.html."""
    start = page.index('id="replay-data">') + len('id="replay-data">')
    return json.loads(page[start:page.index("</script>", start)].replace("<\\/", "</"))


def assert_self_contained_page(page):
    assert page.startswith("<!DOCTYPE html>") and page.rstrip().endswith("</html>")
    assert "<script src" not in page and "<link" not in page and "http://" not in page and "https://" not in page


def test_an_arena_run_with_a_kept_map_writes_its_map_png_and_a_replay_of_its_history_in_metres(controller_file, tmp_path):
    out = tmp_path / "out"
    status, stdout, err = run_controller(controller_file(KEEP_MAP_DRIVE), "--world", world("thick_arena.xml"),
                                         "--out", str(out))
    assert status == 0, err
    assert sorted(os.listdir(out)) == ["controller.log", "controller_lines.csv", "map.png", "replay.html", "summary.json", "trace.csv", "truth.png"]
    assert f"wrote {out}/: map.png, truth.png, summary.json, trace.csv, replay.html, controller.log, controller_lines.csv" in err.splitlines()
    assert summary_of(stdout)["map"] == "kept, 34 x 34 cells of 0.5 m from (-8.50, -8.50)"
    assert json.loads((out / "summary.json").read_text())["map"] == "kept"

    # map.png as room's: the map's tones (never observed blue-grey, occupied dark, free light), the path in red
    pixels = png_pixels((out / "map.png").read_bytes())
    height, width, _ = pixels.shape
    assert 600 <= width <= 2400 and 600 <= height <= 2400
    colours = set(map(tuple, pixels.reshape(-1, 3).tolist()))
    assert (150, 160, 190) in colours and (220, 30, 30) in colours
    assert any(r == g == b and r <= 70 for r, g, b in colours) and any(r == g == b and 215 <= r < 255 for r, g, b in colours)

    page = (out / "replay.html").read_text()
    assert_self_contained_page(page)
    data = replay_data(page)
    assert data["units"] == "metres" and (data["width"], data["height"], data["k"]) == (34, 34, 1)
    assert data["cell_size_m"] == 0.5 and data["origin"] == [-8.5, -8.5]
    assert data["boundary_mm"] == [0, 0, 17000, 17000] and data["body_mm"] == 90
    assert len(data["path"]["steps"]) == 40 and data["path"]["steps"][-1] == 40
    frames = data["frames"]
    assert len(frames["step"]) == 40 and frames["step"][-1] == 40 and frames["t_ms"][-1] == 1280
    changes = frames["changes"]
    assert changes[0] == []  # the first step: nothing mapped yet
    assert all(len(c) > 0 for c in changes[1:34])  # a new cell a step, a frame a step on 1156 cells
    # the last frame holds the map as the controller left it: its north-east cell, (gap, value) last
    assert sum(changes[-1][::2]) == 34 * 34 - 1 and changes[-1][-1] == 2 * 300 + 1


def test_an_arena_run_without_a_kept_map_writes_a_replay_of_the_path_and_says_why_there_is_no_map_png(controller_file, tmp_path):
    out = tmp_path / "out"
    status, stdout, err = run_controller(controller_file(DRIVE), "--world", world("thick_arena.xml"), "--out", str(out))
    assert status == 0, err
    assert sorted(os.listdir(out)) == ["controller.log", "controller_lines.csv", "replay.html", "summary.json", "trace.csv", "truth.png"]
    assert summary_of(stdout)["map"] == ("none kept (maze_mapper.keep_map hands the runner a metric map: map.png, "
                                         "the replay's map)")
    png = (out / "truth.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", png[16:24])
    assert width >= 400 and height >= 400  # 400 cells on the arena's longer side, and the legend
    summary = json.loads((out / "summary.json").read_text())
    assert summary["arena"] and summary["goal"] == "not reached" and summary["steps"] == 40 and summary["map"] == "none"
    page = (out / "replay.html").read_text()
    assert_self_contained_page(page)
    data = replay_data(page)
    assert data["units"] == "metres" and data["caption"] == "thick_arena.xml: no map kept (maze_mapper.keep_map)"
    assert len(data["path"]["steps"]) == 40 and len(data["frames"]["step"]) == 40
    assert all(c == [] for c in data["frames"]["changes"])  # the path only, over a map never observed


def test_a_maze_run_without_a_kept_grid_draws_the_walls_and_the_body_s_path_in_metres_with_no_score(controller_file, tmp_path):
    out = tmp_path / "out"
    status, stdout, err = run_controller(controller_file(DRIVE), "--world", world("maze8x8.txt"), "--out", str(out))
    assert status == 0, err
    assert sorted(os.listdir(out)) == ["controller.log", "controller_lines.csv", "replay.html", "summary.json", "trace.csv", "truth.png"]
    summary = json.loads((out / "summary.json").read_text())
    assert summary["grid"] == "none" and "wall_accuracy" not in summary and "coverage" not in summary
    # truth.png: the world's walls in ink and the path in red, no wall painted red as missed
    pixels = png_pixels((out / "truth.png").read_bytes()).reshape(-1, 3)
    ink = int(((pixels == (20, 20, 20)).all(axis=1)).sum())
    red = int(((pixels == (220, 30, 30)).all(axis=1)).sum())
    assert 0 < red < ink / 4
    # replay.html: in metres, the world's walls drawn, the path every pose of trace.csv
    data = replay_data((out / "replay.html").read_text())
    assert data["units"] == "metres" and len(data["solids_mm"]) > 0
    with open(out / "trace.csv") as f:
        rows = list(csv.reader(f))[1:]
    ox, oy = data["origin"]
    driven = [(round((float(r[2]) - ox) * 1000), round((float(r[3]) - oy) * 1000)) for r in rows]
    path = list(zip(data["path"]["xy_mm"][0::2], data["path"]["xy_mm"][1::2]))
    assert len(path) == len(driven) == 40
    assert all(abs(a - c) <= 1 and abs(b - d) <= 1 for (a, b), (c, d) in zip(path, driven))
    assert len(set(path)) > 3  # the body's poses, not a few cell centres


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
    assert sorted(os.listdir(out)) == ["controller.log", "controller_lines.csv", "notes.txt", "replay.html", "summary.json", "trace.csv", "truth.png"]


def test_a_maze_run_starts_where_a_supervisor_set_the_robot_down_before_it_moved(controller_file, tmp_path):
    # The course's library teleports the robot to a random start after its first step: the
    # pictures and the replay start there, not in the cell it stood in for that one step.
    out = tmp_path / "out"
    source = ("from controller import Supervisor\nimport math\nsup = Supervisor()\nsup.step(32)\n"
              "sup.getSelf().getField('translation').setSFVec3f([2.5, 0.5, 0.0])\n"
              "left, right = sup.getDevice('left motor'), sup.getDevice('right motor')\n"
              "for m in (left, right):\n    m.setPosition(math.inf)\n    m.setVelocity(2.0)\n"
              "for _ in range(10):\n    sup.step(32)\n")
    status, stdout, err = run_controller(controller_file(source), "--world", world("lab4x4.txt"), "--out", str(out))
    assert status == 0, err
    with open(out / "trace.csv") as f:
        rows = list(csv.reader(f))[1:]
    x, y = float(rows[1][2]), float(rows[1][3])
    assert abs(x - 2.5) < 0.01 and abs(y - 0.5) < 0.01  # the step after the teleport
    data = replay_data((out / "replay.html").read_text())
    size_mm = round(data["cell_size_m"] * 1000)
    ox, oy = data["origin"]
    cell = (int((x - ox) // data["cell_size_m"]), int((y - oy) // data["cell_size_m"]))
    first = data["path"]["xy_mm"][:2]
    assert (first[0] // size_mm, first[1] // size_mm) == cell  # the replay's start is the teleported cell
    stood = (int((float(rows[0][2]) - ox) // data["cell_size_m"]), int((float(rows[0][3]) - oy) // data["cell_size_m"]))
    assert stood != cell  # the cell of the first step, before the teleport: not in the path
    assert all((data["path"]["xy_mm"][i] // size_mm, data["path"]["xy_mm"][i + 1] // size_mm) != stood
               for i in range(0, len(data["path"]["xy_mm"]), 2))
