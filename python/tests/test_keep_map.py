"""maze_mapper.keep_map: a controller's metric map as the runner reads it (map.png and the
replay on an arena), and the lines it says when it cannot read one."""

import math

import numpy as np
import pytest

import maze_mapper


def test_an_array_of_log_odds_is_read_row_by_row_from_the_south_with_its_origin_and_cell_size():
    grid = np.zeros((2, 3))
    grid[1, 2] = 1.5  # the north-east cell
    kept = maze_mapper.keep_map(grid, origin=(-1.5, -1.0), cell_size_m=1.0)
    assert (kept.cells_x, kept.cells_y, kept.cell_size_m, kept.origin) == (3, 2, 1.0, (-1.5, -1.0))
    assert kept.log_odds[1, 2] == 1.5 and kept.log_odds.sum() == 1.5
    assert str(kept) == "3 x 2 cells of 1 m from (-1.50, -1.00)"


def test_the_runner_reads_the_array_as_the_controller_changes_it_in_place():
    grid = np.zeros((2, 2), dtype=np.float32)
    kept = maze_mapper.keep_map(grid, origin=(0, 0), cell_size_m=0.5)
    grid[0, 0] -= 0.85
    assert kept.log_odds[0, 0] == pytest.approx(-0.85)


def test_probabilities_become_log_odds_and_nan_or_a_value_outside_0_to_1_is_never_observed():
    p = np.array([[0.5, 0.9, 0.0], [np.nan, -1.0, 1.0]])
    kept = maze_mapper.keep_map(p, origin=(0, 0), cell_size_m=1.0, values="probability")
    assert kept.log_odds[0, 1] == pytest.approx(math.log(9.0), rel=1e-6)
    assert list(kept.log_odds[0, ::2]) == [0.0, -100.0] and list(kept.log_odds[1]) == [0.0, 0.0, 100.0]


def test_base_10_log_odds_use_the_model_s_base_and_prior():
    model = maze_mapper.SensorModel(log_base="10", prior=0.4)
    p = np.array([[0.4, 0.99999]])
    kept = maze_mapper.keep_map(p, origin=(0, 0), cell_size_m=1.0, values="probability", model=model)
    assert kept.log_odds[0, 0] == pytest.approx(model.prior_log_odds) and kept.log_odds[0, 1] == pytest.approx(5.0, abs=1e-3)


def test_an_occupancy_grid_is_kept_as_its_sub_cells_with_its_own_origin_and_cell_size():
    grid = maze_mapper.OccupancyGrid(2, 1, subcells=3, cell_size_m=0.9, origin=(1.0, 2.0))
    grid.array[0, 1, 0, 2] = 2.0  # cell (1, 0), its north-east sub-cell
    kept = maze_mapper.keep_map(grid)
    assert (kept.cells_x, kept.cells_y, kept.origin) == (6, 3, (1.0, 2.0))
    assert kept.cell_size_m == pytest.approx(0.3)
    assert kept.log_odds[2, 5] == 2.0 and kept.log_odds.sum() == 2.0


@pytest.mark.parametrize("call, message", [
    (lambda: maze_mapper.keep_map(np.zeros((2, 2, 2)), origin=(0, 0), cell_size_m=1),
     "error: keep_map: the map must be a 2-D array of numbers, map[j, i] (row j from the south, column i from the west)"),
    (lambda: maze_mapper.keep_map(np.array([["a"]]), origin=(0, 0), cell_size_m=1),
     "error: keep_map: the map must be a 2-D array of numbers, map[j, i] (row j from the south, column i from the "
     "west) (got dtype <U1)"),
    (lambda: maze_mapper.keep_map(np.zeros((2, 2))),
     "error: keep_map: an array needs origin=(x_m, y_m), its south-west corner, and cell_size_m, its cells' side in "
     "metres"),
    (lambda: maze_mapper.keep_map(np.zeros((2, 2)), origin=(0, 0), cell_size_m=0),
     "error: keep_map: cell_size_m must be a length above 0 (got 0)"),
    (lambda: maze_mapper.keep_map(np.zeros((2, 2)), origin=(math.nan, 0), cell_size_m=1),
     "error: keep_map: origin must be the map's south-west corner in metres (got (nan, 0))"),
    (lambda: maze_mapper.keep_map(np.zeros((0, 2)), origin=(0, 0), cell_size_m=1),
     "error: keep_map: the map must have 1 to 20000 cells a side (got 0 rows x 2 columns)"),
    (lambda: maze_mapper.keep_map(np.zeros((2, 2)), origin=(0, 0), cell_size_m=1, values="percent"),
     "error: keep_map: values must be log_odds or probability (got 'percent')"),
    (lambda: maze_mapper.keep_map(maze_mapper.OccupancyGrid(1, 1), origin=(0, 0)),
     "error: keep_map: an OccupancyGrid carries its own origin, cell size and model (give only the grid)"),
])
def test_a_map_the_runner_cannot_draw_is_refused_in_one_line(call, message):
    with pytest.raises(maze_mapper.Error) as raised:
        call()
    assert str(raised.value) == message


def test_an_array_reshaped_after_it_was_kept_says_so():
    grid = np.zeros((4, 4))
    kept = maze_mapper.keep_map(grid, origin=(0, 0), cell_size_m=1)
    grid.shape = (2, 8)
    with pytest.raises(maze_mapper.Error) as raised:
        kept.log_odds
    assert str(raised.value) == "error: the kept map's shape is now 2 x 8, kept as 4 x 4 (keep_map it again)"
