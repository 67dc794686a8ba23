"""The program's ASCII map and K x K matrix, applied to a student's own arrays."""

import numpy as np
import pytest

import maze_mapper

W, F = 0.41, -0.85


def corridor():
    """A 2 x 1 maze made by hand, grid[y, x, i, j]: walls all round, open between the cells."""
    grid = np.zeros((1, 2, 3, 3))
    grid[0, 0] = [[W, W, W], [W, F, F], [W, W, W]]
    grid[0, 1] = [[W, W, W], [F, F, W], [W, W, W]]
    return grid


def test_a_hand_made_array_prints_as_the_lab_prints_it():
    text = maze_mapper.render(corridor(), {(0, 0): "E", (1, 0): "W"})
    assert text == "WWWWWW\nW→  ←W\nWWWWWW\n"
    assert maze_mapper.render(corridor(), {(0, 0): "E"}, ascii=True) == "WWWWWW\nW>   W\nWWWWWW\n"
    assert maze_mapper.format_cell_matrix(corridor(), 0, 0) == "+0.41 +0.41 +0.41\n+0.41 -0.85 -0.85\n+0.41 +0.41 +0.41\n"


def test_rows_go_north_up_from_the_southern_row_0():
    grid = np.zeros((2, 1, 3, 3), dtype=np.float32)
    grid[0, 0, 2, :] = 1.0  # the southern row's south band
    assert maze_mapper.render(grid) == "   \n   \n   \n   \n   \nWWW\n"
    # Any strides: the rows flipped, the band stays the cell's south band.
    assert maze_mapper.render(grid[::-1]) == "   \n   \nWWW\n   \n   \n   \n"


def test_nested_lists_and_integers_are_arrays_too():
    assert maze_mapper.render(corridor().tolist()) == maze_mapper.render(corridor().astype(np.float32))
    assert maze_mapper.render(np.ones((1, 1, 3, 3), dtype=int)) == "WWW\nWWW\nWWW\n"


def test_a_grid_renders_the_same_as_its_array():
    grid = maze_mapper.OccupancyGrid(2, 1)
    grid.array[:] = corridor()
    grid.visit(0, 0, "E")
    assert grid.render() == maze_mapper.render(grid.array, grid) == maze_mapper.render(grid)


def test_unknown_and_threshold():
    grid = np.full((1, 1, 3, 3), 0.0)
    grid[0, 0, 1, :] = -0.2
    grid[0, 0, 0, 0] = 0.1
    assert maze_mapper.render(grid, unknown="?") == "W??\n   \n???\n"
    assert maze_mapper.render(grid, threshold=-0.5) == "W  \nWWW\n   \n"  # never observed: never W
    assert maze_mapper.render(grid, initial_log_odds=-0.2, unknown=".") == "W  \n...\n   \n"


@pytest.mark.parametrize("array, message", [
    (np.zeros((3, 3)), r"^error: the grid must have the shape rows x columns x K x K \(got \(3, 3\)\)$"),
    (np.zeros((1, 1, 3, 2)), r"^error: the grid must have the shape rows x columns x K x K \(got \(1, 1, 3, 2\)\)$"),
    ("walls", r"^error: the grid must be an array of numbers, rows x columns x K x K$"),
])
def test_a_wrong_shape_says_what_it_got(array, message):
    with pytest.raises(maze_mapper.Error, match=message):
        maze_mapper.render(array)


def test_k_must_be_odd_and_cells_inside():
    with pytest.raises(maze_mapper.Error, match=r"^error: .*"):
        maze_mapper.render(np.zeros((2, 2, 4, 4)))
    with pytest.raises(maze_mapper.Error, match=r"^error: visited cell \(2,0\) is outside the 2x1 grid$"):
        maze_mapper.render(corridor(), {(2, 0): "N"})
    with pytest.raises(maze_mapper.Error, match=r"^error: cell \(0,1\) is outside the 2x1 grid$"):
        maze_mapper.format_cell_matrix(corridor(), 0, 1)
