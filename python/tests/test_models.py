"""The cell and ray models fed a 360-beam range image and a pose, as a controller has them."""

import math

import numpy as np
import pytest

import maze_mapper

BEAMS = 360


def wrap(a):
    return (a + math.pi) % (2 * math.pi) - math.pi


def range_image(yaw, walls, distance=0.494):
    """A 360-beam image in Webots' order (beam i at pi - i degrees from the heading) from a
    cell's centre: walls in the world directions named ('N', 'E', 'S', 'W') at `distance`
    along the axis and further off it, as a square box's sides; no return elsewhere."""
    axes = {"N": math.pi / 2, "E": 0.0, "S": -math.pi / 2, "W": math.pi}
    ranges = np.full(BEAMS, np.inf, dtype=np.float32)
    for i in range(BEAMS):
        world = yaw + math.pi - i * 2 * math.pi / BEAMS
        for side in walls:
            off = wrap(world - axes[side])
            if abs(off) < math.pi / 4 + 1e-9:
                ranges[i] = min(ranges[i], distance / math.cos(off))
    return ranges


def test_cell_model_marks_the_classroom_matrix():
    grid = maze_mapper.OccupancyGrid(2, 2)
    ranges = range_image(math.pi / 2, "NW")
    updated = maze_mapper.CellModel().update(grid, ranges, (0.5, 0.5), math.pi / 2, max_range_m=3.0,
                                             min_range_m=0.07)
    assert updated == 8
    assert grid.cell_matrix(0, 0) == "+0.41 +0.41 +0.41\n+0.41 -0.85 -0.85\n+0.41 -0.85 +0.00\n"
    assert [grid.side(0, 0, h) for h in "NESW"] == ["wall", "open", "open", "wall"]
    assert not grid.array[:, 1].any() and not grid.array[1].any()  # only the robot's cell


def test_cell_model_at_k5_marks_whole_bands():
    grid = maze_mapper.OccupancyGrid(1, 1, subcells=5)
    maze_mapper.CellModel().update(grid, range_image(0.0, "NESW"), (0.5, 0.5), 0.0, max_range_m=3.0)
    band = np.float32(math.log(1.5))
    m = grid.array[0, 0]
    assert np.all(m[0] == band) and np.all(m[4] == band) and np.all(m[:, 0] == band) and np.all(m[:, 4] == band)
    assert m[2, 2] == np.float32(math.log(3 / 7)) and m[1, 2] == np.float32(math.log(3 / 7))
    assert m[1, 1] == 0.0  # off the paths: untouched


def test_ray_model_traces_every_beam():
    grid = maze_mapper.OccupancyGrid(1, 1)
    maze_mapper.RayModel().update(grid, range_image(1.0, "NESW"), (0.5, 0.5), 1.0, max_range_m=3.0)
    m = grid.array[0, 0]
    occupied = np.float32(math.log(1.5))
    assert m[1, 1] == np.float32(math.log(3 / 7))
    assert all(m[i, j] == occupied for i in range(3) for j in range(3) if (i, j) != (1, 1))


def test_the_cell_comes_from_the_position_unless_given():
    grid = maze_mapper.OccupancyGrid(3, 1)
    maze_mapper.CellModel().update(grid, range_image(0.0, "NS"), (2.5, 0.5), 0.0, max_range_m=3.0)
    assert grid.side(2, 0, "N") == "wall" and grid.side(0, 0, "N") == "unknown"
    maze_mapper.CellModel().update(grid, range_image(0.0, "NS"), (2.5, 0.5), 0.0, max_range_m=3.0, cell=(1, 0))
    assert grid.side(1, 0, "S") == "wall"


def test_any_sequence_of_numbers_is_a_range_image():
    grid = maze_mapper.OccupancyGrid(1, 1)
    as_list = [float(r) for r in range_image(0.0, "NESW")]
    maze_mapper.CellModel().update(grid, as_list, (0.5, 0.5), 0.0, max_range_m=3.0)
    assert [grid.side(0, 0, h) for h in "NESW"] == ["wall"] * 4


@pytest.mark.parametrize("kwargs, message", [
    ({"max_range_m": 0.0}, r"^error: the lidar's range must satisfy 0 <= min_range_m < max_range_m"),
    ({"max_range_m": 3.0, "fov_rad": 7.0}, r"^error: fov_rad must be in \(0, 2 pi\] \(got 7\)$"),
    ({"max_range_m": 3.0, "cell": (5, 0)}, r"^error: cell \(5,0\) is outside the 1x1 grid$"),
])
def test_bad_readings_raise(kwargs, message):
    grid = maze_mapper.OccupancyGrid(1, 1)
    with pytest.raises(maze_mapper.Error, match=message):
        maze_mapper.CellModel().update(grid, range_image(0.0, "N"), (0.5, 0.5), 0.0, **kwargs)
    with pytest.raises(maze_mapper.Error, match=r"^error: the pose \(7, 0.5\) is outside the grid$"):
        maze_mapper.CellModel().update(grid, range_image(0.0, "N"), (7.0, 0.5), 0.0, max_range_m=3.0)
    with pytest.raises(maze_mapper.Error):
        maze_mapper.RayModel(hit_depth=99)
