"""Worlds in every format, and the scorer against the program's own run."""

import numpy as np
import pytest

import maze_mapper
from conftest import REPO, final_map, program, summary_of, world


@pytest.mark.parametrize("name", ["lab4x4.txt", "lab4x4.num", "lab4x4.xml"])
def test_worlds_load_from_every_format(name):
    w = maze_mapper.load_world(world(name))
    _, shown, _ = program("show", f"worlds/{name}")
    assert w.text() == shown
    assert (w.width, w.height, w.cell_size_m) == (4, 4, 1.0)
    assert w.has_wall(0, 0, "W") and w.has_wall(0, 0, "S")
    assert w.start == (0, 0)


def test_cell_size_for_text_worlds():
    assert maze_mapper.load_world(world("lab4x4.txt"), cell_size_m=0.18).cell_size_m == pytest.approx(0.18)


@pytest.mark.parametrize("path", ["tests/data/worlds/inconsistent.num", "no/such/world.txt"])
def test_a_bad_world_raises_the_programs_message(path, monkeypatch):
    status, _, stderr = program("show", path, check=False)
    assert status == 2
    monkeypatch.chdir(REPO)  # the same path as the user typed it, in the message
    with pytest.raises(maze_mapper.Error) as raised:
        maze_mapper.load_world(path)
    assert str(raised.value) == stderr.strip()


@pytest.mark.parametrize("name, subcells", [("lab4x4.txt", 3), ("maze8x8.txt", 5)])
def test_the_scorer_reports_what_run_reports_on_the_same_grid(name, subcells):
    w = maze_mapper.load_world(world(name))
    grid, run = maze_mapper.explore_world(w, subcells=subcells)
    _, out, _ = program("run", f"worlds/{name}", "--quiet", "--subcells", str(subcells))
    summary = summary_of(out)
    # The same grid: the program's printed map, and its step count.
    assert grid.render() == final_map(out, w.height * subcells)
    assert str(run["steps"]) == summary["steps"] and run["end"] == summary["end"]
    for source in (grid, grid.array):  # the grid, or a copy of its array as a student's
        result = maze_mapper.score(w, source, None if source is grid else grid)
        assert f"{result.coverage_percent:.2f}%" == summary["coverage"]
        assert f"{result.wall_accuracy_percent:.2f}%" == summary["wall_accuracy"]
        assert str(result.reachable_cells) == summary["reachable"]


def test_the_scorer_names_the_wrong_sides():
    w = maze_mapper.load_world(world("lab4x4.txt"))
    grid, _ = maze_mapper.explore_world(w)
    student = grid.array.astype(np.float64)
    student[0, 0, 1, 0] = -0.85  # (0,0)'s west wall forgotten
    student[0, 0, 1, 2] = 0.41   # a wall east of (0,0) that is not there
    result = maze_mapper.score(w, student, grid)
    assert sorted(repr(s) for s in result.wrong_sides) == [
        "E of (0,0) a wall that is not there", "W of (0,0) a wall missed"]
    assert result.wrong_where_looked == 2
    assert result.sides - result.sides_correct == 2
    empty = maze_mapper.score(w, np.zeros((4, 4, 3, 3)))
    assert (empty.coverage_percent, empty.wall_accuracy_percent) == (0.0, 0.0)
    assert all(s.verdict in ("a wall missed", "an opening never seen") for s in empty.wrong_sides)


def test_a_grid_of_another_size_is_refused():
    w = maze_mapper.load_world(world("lab4x4.txt"))
    with pytest.raises(maze_mapper.Error, match=r"^error: the grid is 3x4 cells, the world 4x4$"):
        maze_mapper.score(w, np.zeros((4, 3, 3, 3)))
