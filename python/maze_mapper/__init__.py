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

import functools
import os
import re

from ._native import (
    CellModel,
    Error,
    KeptMap,
    NoSpaceError,
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
    "ArgumentTypeError", "CellModel", "Error", "NoSpaceError", "OccupancyGrid", "RayModel", "Score", "SensorModel",
    "World", "explore_world", "format_cell_matrix", "keep_grid", "keep_map", "load_world", "log_odds",
    "probability", "render", "score", "user_path",
]


class ArgumentTypeError(Error, TypeError):
    """An argument of the wrong type (a word where a number goes): a maze_mapper.Error like
    every other bad input, and a TypeError as Python's own functions raise."""


# pybind11 reports a call no signature accepts with a TypeError of its own, over several lines
# ("log_odds(): incompatible function arguments. The following argument types are
# supported:\n    1. (p: float, base: object = 'e') -> float\n\nInvoked with: 'x'"); it
# becomes one line in the program's form, naming what was given by its types.
_PYBIND_MISMATCH = re.compile(r"^[\w.]+\(\): incompatible (?:function|constructor) arguments")


def _one_line(shown, text, args, kwargs):
    text = re.sub(r"<([\w.]+) object at 0x[0-9a-f]+>", r"\1()", text).replace("maze_mapper._native.", "")
    signatures = re.findall(r"^\s+\d+\. (.*)$", text, re.MULTILINE)
    takes = " or ".join(
        re.sub(r"self: [\w.]+(, )?", "", re.sub(r"^[\w.]*\(", "(", s)).split(" -> ")[0] for s in signatures)
    given = [type(a).__name__ for a in args] + [f"{k}={type(v).__name__}" for k, v in kwargs.items()]
    return f"error: {shown}() takes {takes}, not ({', '.join(given)})"


def _wrong_types_raise_error(function, shown, method):
    @functools.wraps(function)
    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except TypeError as wrong:
            if isinstance(wrong, Error) or not _PYBIND_MISMATCH.match(str(wrong)):
                raise
            given = args[1:] if method else args
            raise ArgumentTypeError(_one_line(shown, str(wrong), given, kwargs)) from None
    return call


def _raise_error_for_wrong_types():
    """Wraps the native functions and the methods of the native classes above."""
    names = globals()
    for name in ("explore_world", "format_cell_matrix", "load_world", "log_odds", "probability", "render", "score"):
        names[name] = _wrong_types_raise_error(names[name], name, False)
    for cls in (CellModel, KeptMap, OccupancyGrid, RayModel, Score, SensorModel, World):
        for attribute, value in list(vars(cls).items()):
            if callable(value) and (attribute == "__init__" or not attribute.startswith("_")):
                shown = cls.__name__ if attribute == "__init__" else f"{cls.__name__}.{attribute}"
                setattr(cls, attribute, _wrong_types_raise_error(value, shown, True))


_raise_error_for_wrong_types()

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

# The metric map a controller handed to keep_map (a KeptMap), and the run's files that record
# it as the run goes (the runner sets them).
_kept_map = None
_map_recorder = None


def keep_map(map, *, origin=None, cell_size_m=None, model=None, values="log_odds"):
    """Hands the runner (python3 -m maze_mapper.run) the metric map this controller maps into,
    for map.png and the replay's map on an arena (--out): a NumPy 2-D array map[j, i], row j
    from the south and column i from the west (an array whose row 0 is the northern row is
    `array[::-1]`), with `origin` its south-west corner (x_m, y_m) and `cell_size_m` its cells'
    side; or an OccupancyGrid (its sub-cells, origin and model). Values are log-odds in
    `model`'s base (a SensorModel, the classroom one by default), or with
    values="probability" probabilities; NaN (and, for probabilities, a value outside 0 ... 1)
    is never observed, as is l(prior). The runner keeps the array itself and reads it as the
    run goes and when it ends: update it in place, or keep_map the new one. Raises
    maze_mapper.Error for a map or extent it cannot draw."""
    global _kept_map
    _kept_map = KeptMap(map, origin=origin, cell_size_m=cell_size_m, model=model, values=values)
    if _map_recorder is not None:
        _map_recorder.keep_map(_kept_map)
    return _kept_map


# The folder python3 -m maze_mapper.run was started in, while it runs a controller (it runs
# the controller in the controller's own folder).
_started_in = None


def user_path(path):
    """A path the user typed on the runner's command line, such as a controller's argument
    (lab_mapper's --save-grid), taken from the folder the runner was started in, where the user
    typed it: the controller itself runs in its own folder, as Webots runs it, so the paths it
    opens as they are (its world file) are taken from there. Outside the runner, or for an
    absolute path, the path as given."""
    path = os.fspath(path)
    if _started_in is None or os.path.isabs(path):
        return path
    return os.path.join(_started_in, path)
