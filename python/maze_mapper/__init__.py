"""maze_mapper for Python: the lab's 4D occupancy grid, its models, the map renderer and the
scorer, over the same C++ code as the `maze_mapper` program; and Webots' Python controller
API, the Supervisor included, over its embedded simulator (python3 -m maze_mapper.run
CONTROLLER.py [--world WORLD]): the course's own controllers run unchanged (docs/course.md).

The grid's layout, for the program's grids and for a student's own NumPy arrays alike:

    grid[y, x, i, j]   shape (rows, columns, K, K), float log-odds
        y  cell row from the south (0 = the southern row)   x  cell column from the west
        i  sub-cell row from the north (0 = the north band)  j  sub-cell column from the west

(an array whose row 0 is the northern row is `array[::-1]` in this layout). Bad input raises
maze_mapper.Error (a ValueError) carrying the line the program prints. NumPy is needed for
the arrays, not to import the package. Students' guide: docs/python.md.
"""

from ._native import (
    CellModel,
    Error,
    OccupancyGrid,
    RayModel,
    Score,
    SensorModel,
    World,
    explore_world,
    format_cell_matrix,
    load_world,
    log_odds,
    probability,
    render,
    score,
)

__all__ = [
    "CellModel", "Error", "OccupancyGrid", "RayModel", "Score", "SensorModel", "World",
    "explore_world", "format_cell_matrix", "keep_grid", "load_world", "log_odds",
    "probability", "render", "score",
]

# What a controller handed to keep_grid, for the runner to score when the controller ends.
_kept = None


def keep_grid(grid, visited=None, *, initial_log_odds=None):
    """Hands the runner (python3 -m maze_mapper.run) the grid this controller maps into: an
    OccupancyGrid, or a NumPy array of shape (rows, columns, K, K) in the layout above with
    `visited` the cells the robot stood in ({(x, y): 'N'|'E'|'S'|'W'} or (x, y) pairs). The
    runner scores it, as it is when the controller ends, against the world's truth and
    prints coverage and wall accuracy. Outside a run it only remembers the grid."""
    global _kept
    _kept = (grid, visited, initial_log_odds)
