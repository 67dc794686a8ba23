"""Numbers the Python API refuses with maze_mapper.Error, as the program refuses them: NaN,
infinities and values out of range, and arguments of the wrong type."""

import math

import numpy as np
import pytest

import maze_mapper
from conftest import run_controller, summary_of, world


@pytest.mark.parametrize("p", [2.0, -0.5, 0.0, 1.0, math.nan])
def test_log_odds_of_no_probability_is_an_error_not_nan(p):
    with pytest.raises(maze_mapper.Error, match=r"^error: log_odds: p must be a probability strictly between 0 and 1"):
        maze_mapper.log_odds(p)


def test_probability_of_nan_is_an_error_and_of_infinities_a_certainty():
    with pytest.raises(maze_mapper.Error, match=r"^error: probability: log_odds must be a number \(got nan\)$"):
        maze_mapper.probability(math.nan)
    assert maze_mapper.probability(math.inf) == 1.0
    assert maze_mapper.probability(-math.inf) == 0.0


@pytest.mark.parametrize("cell_size_m", [math.nan, -0.5, 0.0, math.inf])
def test_a_cell_size_that_is_no_length_is_refused(cell_size_m):
    with pytest.raises(maze_mapper.Error, match=r"^error: "):
        maze_mapper.OccupancyGrid(2, 2, cell_size_m=cell_size_m)
    with pytest.raises(maze_mapper.Error, match=r"^error: "):
        maze_mapper.load_world(world("lab4x4.txt"), cell_size_m=cell_size_m)


@pytest.mark.parametrize("position, yaw", [((0.5, 0.5), math.nan), ((math.nan, 0.5), 0.0), ((0.5, math.inf), 0.0)])
def test_a_pose_that_is_not_finite_is_refused_and_marks_nothing(position, yaw):
    grid = maze_mapper.OccupancyGrid(1, 1)
    before = grid.array.copy()
    with pytest.raises(maze_mapper.Error, match=r"^error: the pose must be finite numbers"):
        maze_mapper.CellModel().update(grid, np.full(360, 0.5, dtype=np.float32), position, yaw, max_range_m=3.0)
    assert np.array_equal(grid.array, before)


@pytest.mark.parametrize("call", [
    lambda: maze_mapper.log_odds("x"),
    lambda: maze_mapper.OccupancyGrid("four", 4),
    lambda: maze_mapper.OccupancyGrid(4, 4).visit("0", 0, "N"),
    lambda: maze_mapper.SensorModel(p_free="low"),
    lambda: maze_mapper.load_world(42),
])
def test_a_wrong_argument_type_raises_maze_mapper_error_in_one_line(call):
    with pytest.raises(maze_mapper.Error) as raised:
        call()
    assert isinstance(raised.value, TypeError)  # what Python's own functions raise, too
    message = str(raised.value)
    assert message.startswith("error: ") and "\n" not in message


def test_the_wrong_type_message_says_what_is_taken_and_what_was_given():
    with pytest.raises(maze_mapper.Error) as raised:
        maze_mapper.OccupancyGrid(4, 4).visit("0", 0, "N")
    assert str(raised.value) == "error: OccupancyGrid.visit() takes (x: int, y: int, heading: str), not (str, int, str)"


def test_a_step_of_no_time_passes_no_time_and_a_negative_one_is_an_error(controller_file):
    source = ('from controller import Robot\nimport maze_mapper\nr = Robot()\n'
              'print("zero", r.step(0), r.getTime())\n'
              'try:\n    r.step(-1)\nexcept maze_mapper.Error as e:\n    print("negative", e)\n'
              'print("time", r.getTime())\nr.step(32)\nprint("one", r.getTime())\n')
    status, out, err = run_controller(controller_file(source), "--world", "worlds/lab4x4.txt")
    assert status == 0, err
    lines = out.splitlines()
    assert "zero 0 0.0" in lines
    assert "negative error: Robot.step: the duration must be 0 or more ms (got -1)" in lines
    assert "time 0.0" in lines
    assert "one 0.032" in lines
    assert summary_of(out)["steps"] == "1"
