"""The 4D grid as a NumPy view, and the sensor model's numbers."""

import math

import numpy as np
import pytest

import maze_mapper
from conftest import program


def test_the_array_is_the_grid_itself_rows_columns_k_k():
    grid = maze_mapper.OccupancyGrid(4, 3, subcells=5)
    a = grid.array
    assert a.shape == (3, 4, 5, 5)
    assert a.dtype == np.float32
    assert a.flags.c_contiguous and a.flags.writeable
    a[2, 1, 0, 2] = 1.5  # row 2 (from the south), column 1, the north band's middle
    assert np.shares_memory(a, grid.array)
    assert grid.cell_matrix(1, 2).splitlines()[0] == "+0.00 +0.00 +1.50 +0.00 +0.00"
    assert grid.side(1, 2, "N") == "wall"


def test_the_view_keeps_the_grid_alive():
    a = maze_mapper.OccupancyGrid(2, 2).array
    a[:] = -0.5
    assert float(a.sum()) == pytest.approx(-0.5 * 36)


def test_a_new_grid_holds_the_prior_and_every_side_is_unknown():
    grid = maze_mapper.OccupancyGrid(2, 2, model=maze_mapper.SensorModel(prior=0.4))
    assert grid.initial_log_odds == pytest.approx(math.log(0.4 / 0.6), abs=1e-6)
    assert np.all(grid.array == np.float32(grid.initial_log_odds))
    assert grid.side(0, 0, "E") == "unknown"


def test_visits_draw_arrows():
    grid = maze_mapper.OccupancyGrid(2, 1)
    grid.visit(1, 0, "E")
    assert grid.visited(1, 0) and not grid.visited(0, 0) and grid.visited_count == 1
    assert grid.render(ascii=True) == "      \n    > \n      \n"


def test_classroom_numbers():
    model = maze_mapper.SensorModel()
    assert model.free_increment == pytest.approx(math.log(0.3 / 0.7))
    assert model.occupied_increment == pytest.approx(math.log(0.6 / 0.4))
    assert model.prior_log_odds == 0.0
    ten = maze_mapper.SensorModel(log_base="10")
    assert round(ten.free_increment, 3) == -0.368
    assert round(maze_mapper.log_odds(0.99999, "10"), 3) == 5.000
    assert maze_mapper.probability(maze_mapper.log_odds(0.7)) == pytest.approx(0.7)
    clamped = maze_mapper.SensorModel(clamp=(-2.0, 3.5))
    assert clamped.update_occupied(3.4) == 3.5


@pytest.mark.parametrize("kwargs, cli", [
    ({"p_occ": 0.4}, ["--p-occ", "0.4"]),
    ({"p_free": 1.5}, ["--p-free", "1.5"]),
    ({"clamp": (1.0, 2.0)}, ["--clamp", "1", "2"]),
])
def test_a_bad_model_raises_the_programs_message(kwargs, cli):
    status, _, stderr = program("explain", *cli, check=False)
    assert status == 2
    with pytest.raises(maze_mapper.Error) as raised:
        maze_mapper.SensorModel(**kwargs)
    assert str(raised.value) == stderr.strip()


def test_a_bad_grid_raises_one_error_line():
    with pytest.raises(maze_mapper.Error, match=r"^error: .*"):
        maze_mapper.OccupancyGrid(4, 4, subcells=4)
    with pytest.raises(maze_mapper.Error, match=r"^error: cell \(4,0\) is outside the 4x4 grid$"):
        maze_mapper.OccupancyGrid(4, 4).visit(4, 0, "N")
    with pytest.raises(maze_mapper.Error, match=r"^error: a heading is N, E, S or W \(got 'up'\)$"):
        maze_mapper.OccupancyGrid(4, 4).visit(0, 0, "up")
