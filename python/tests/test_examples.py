"""The examples, run as a student runs them: the lab-style controller's printed map is the
program's own map for the same world and readings, and its grid is scored."""

import os
import re
import subprocess
import sys

import numpy as np
import pytest

import maze_mapper
from conftest import EXAMPLES, REPO, final_map, run_controller, summary_of, world

LAB_MAPPER = os.path.join(EXAMPLES, "lab_mapper.py")
CHECK_GRID = os.path.join(EXAMPLES, "check_grid.py")
MATRIX = re.compile(r"^cell \((\d+),(\d+)\) log-odds, north row first:\n((?:[-+]\d\.\d\d(?: [-+]\d\.\d\d)*\n)+)", re.M)


def no_arrows(text):
    return re.sub("[↑→↓←]", " ", text)


def replay(scans_file):
    """The program's cell model and renderer over the controller's own readings."""
    s = np.load(scans_file)
    width, height = (int(v) for v in s["size"])
    grid = maze_mapper.OccupancyGrid(width, height, subcells=int(s["subcells"]),
                                     cell_size_m=float(s["cell_size"]), origin=tuple(s["origin"]))
    model = maze_mapper.CellModel()
    for cell, position, yaw, ranges in zip(s["cells"], s["positions"], s["yaws"], s["ranges"]):
        model.update(grid, ranges, tuple(position), float(yaw), max_range_m=float(s["max_range"]),
                     min_range_m=float(s["min_range"]), fov_rad=float(s["fov"]), cell=tuple(int(v) for v in cell))
    for (x, y), h in zip(s["visited"], s["headings"]):
        grid.visit(int(x), int(y), str(h))
    return grid


@pytest.mark.parametrize("name, size, subcells", [("lab4x4.txt", "4x4", 3), ("lab4x4.xml", "4x4", 5),
                                                  ("maze8x8.txt", "8x8", 3)])
def test_the_lab_controllers_map_is_the_programs_for_the_same_readings(name, size, subcells, tmp_path):
    scans = tmp_path / "scans.npz"
    status, out, err = run_controller(LAB_MAPPER, "--world", f"worlds/{name}", "--",
                                      "--size", size, "--subcells", str(subcells), "--save-scans", str(scans))
    assert status == 0, err
    grid = replay(scans)
    rows = grid.height * subcells
    assert final_map(out, rows) == grid.render()
    matrices = MATRIX.findall(out)
    assert len(matrices) == grid.visited_count
    for x, y, matrix in matrices:
        assert matrix == grid.cell_matrix(int(x), int(y))
    # The program's own exploration of the world learns the same walls (the arrows, the
    # route, differ).
    truth = maze_mapper.load_world(world(name))
    programs, _ = maze_mapper.explore_world(truth, subcells=subcells)
    assert no_arrows(final_map(out, rows)) == no_arrows(programs.render())
    # Scored by the runner as `maze_mapper.score` scores the program's grid.
    summary = summary_of(out)
    result = maze_mapper.score(truth, grid)
    assert summary["coverage"] == f"{result.coverage_percent:.2f}%" == "100.00%"
    assert summary["wall_accuracy"] == f"{result.wall_accuracy_percent:.2f}%"
    assert "wrong_sides" not in summary


def test_check_grid_prints_a_hand_made_array_and_its_mistakes():
    done = subprocess.run([sys.executable, CHECK_GRID, world("lab4x4.txt")], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0] == "WWWWWWWWW   "  # (3,3)'s north band never observed
    assert lines[10] == "W↑W ↑WW↑  ↑W"  # a wall east of (0,0) that is not there
    assert lines[13:] == ["coverage: 100.00%", "wall_accuracy: 95.00% (38 of 40 sides)",
                          "wrong: E of (0,0) a wall that is not there", "wrong: N of (3,3) a wall missed"]


def test_check_grid_scores_a_saved_grid(tmp_path):
    saved = tmp_path / "grid.npz"
    status, _, err = run_controller(LAB_MAPPER, "--world", "worlds/lab4x4.txt", "--", "--save-grid", str(saved))
    assert status == 0, err
    done = subprocess.run([sys.executable, CHECK_GRID, world("lab4x4.txt"), str(saved)],
                          capture_output=True, text=True, cwd=REPO)
    assert done.returncode == 0, done.stderr
    assert "wall_accuracy: 100.00% (40 of 40 sides)" in done.stdout.splitlines()
    bad = subprocess.run([sys.executable, CHECK_GRID, world("lab4x4.txt"), str(tmp_path / "none.npz")],
                         capture_output=True, text=True)
    assert bad.returncode != 0
