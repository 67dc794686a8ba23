"""What `grade --controllers` reads from a run's folder for the course's labs: whether the robot
stopped near a landmark (Lab 3, --goal) and how good the position estimates the controller
printed were (Lab 4, --estimate).

Cells are numbered as the course numbers them: row by row from the north-west corner, 1 to N
(a 5 x 5 arena: 1 to 5 the northern row, west to east). On a maze world the lattice is the
maze's; on an arena it is cells of `cell_size_m` laid centred on the arena's floor.
"""

import csv
import math
import os
import re

# The landmark colours --goal names, as (red, green, blue): the course's Landmark cylinders.
COLORS = {"red": (1.0, 0.0, 0.0), "green": (0.0, 1.0, 0.0), "blue": (0.0, 0.0, 1.0), "yellow": (1.0, 1.0, 0.0),
          "cyan": (0.0, 1.0, 1.0), "magenta": (1.0, 0.0, 1.0), "white": (1.0, 1.0, 1.0), "black": (0.0, 0.0, 0.0)}
_SAME_COLOR = 0.25  # each channel within this of the named colour's


def goal_targets():
    """What --goal takes: any landmark, or the landmarks of one colour."""
    return ["landmark", *COLORS]


class Lattice:
    """Cells of size_m from (x_west, y_north), `columns` x `rows`, numbered 1 to N row by row
    from the north-west."""

    def __init__(self, x_west, y_north, size_m, columns, rows):
        self.x_west, self.y_north, self.size_m, self.columns, self.rows = x_west, y_north, size_m, columns, rows

    @classmethod
    def of_world(cls, world, cell_size_m):
        if world.is_maze:
            x0, y0 = world.origin
            return cls(x0, y0 + world.height * world.cell_size_m, world.cell_size_m, world.width, world.height)
        return cls.of_boundary(world.boundary, cell_size_m)

    @classmethod
    def of_boundary(cls, boundary, cell_size_m):
        """Cells of cell_size_m laid centred on the floor (x_min, x_max, y_min, y_max)."""
        x_min, x_max, y_min, y_max = boundary
        columns = max(1, int((x_max - x_min) / cell_size_m + 1e-6))
        rows = max(1, int((y_max - y_min) / cell_size_m + 1e-6))
        x_west = (x_min + x_max - columns * cell_size_m) / 2.0
        y_north = (y_min + y_max + rows * cell_size_m) / 2.0
        return cls(x_west, y_north, cell_size_m, columns, rows)

    def cell(self, x, y):
        """The cell number of a point, or None off the lattice."""
        column = math.floor((x - self.x_west) / self.size_m)
        row = math.floor((self.y_north - y) / self.size_m)
        if 0 <= column < self.columns and 0 <= row < self.rows:
            return row * self.columns + column + 1
        return None

    def centre(self, number):
        """The centre (x, y) of cell `number`, or None when there is no such cell."""
        if not 1 <= number <= self.columns * self.rows:
            return None
        row, column = divmod(number - 1, self.columns)
        return self.x_west + (column + 0.5) * self.size_m, self.y_north - (row + 0.5) * self.size_m


def landmark_gap(summary, target):
    """The smallest gap (m, body edge to cylinder surface) at the run's end to a landmark
    `target` names (goal_targets()), or None when the run's world has none."""
    gaps = [m["gap_m"] for m in summary.get("landmarks") or []
            if target == "landmark" or _is_color(m.get("color") or [], COLORS[target])]
    return min(gaps) if gaps else None


def _is_color(rgb, named):
    return len(rgb) >= 3 and all(abs(a - b) <= _SAME_COLOR for a, b in zip(rgb, named))


def estimate_of(pattern, line):
    """(x, y) or a cell number from a line the pattern matches, else None. The match's groups
    `x` and `y`, or `cell`, when named; else its numbers: two are x and y, one is a cell."""
    match = pattern.search(line)
    if match is None:
        return None
    named = match.groupdict()
    if named.get("x") is not None and named.get("y") is not None:
        return float(named["x"]), float(named["y"])
    if named.get("cell") is not None:
        return int(float(named["cell"]))
    texts = [g for g in match.groups() if g is not None] or re.findall(r"[-+]?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?",
                                                                        match.group(0))
    numbers = []
    for text in texts:
        try:
            numbers.append(float(text))
        except ValueError:
            return None
    if len(numbers) >= 2:
        return numbers[0], numbers[1]
    if len(numbers) == 1 and numbers[0].is_integer():
        return int(numbers[0])
    return None


def _printed_lines(run_dir):
    """(text, true x, true y) of each line controller.log holds, from controller_lines.csv."""
    log_path, lines_path = os.path.join(run_dir, "controller.log"), os.path.join(run_dir, "controller_lines.csv")
    if not (os.path.isfile(log_path) and os.path.isfile(lines_path)):
        return []
    with open(log_path, errors="replace") as f:
        texts = f.read().splitlines()
    with open(lines_path, newline="") as f:
        poses = {int(r["line"]): (float(r["x_m"]), float(r["y_m"])) for r in csv.DictReader(f)}
    return [(text, *poses[n]) for n, text in enumerate(texts, start=1) if n in poses]


def estimate_scores(run_dir, pattern, lattice):
    """{estimates, estimate_error_m (the last one's), right_cell (share, %)}: every line of the
    run's controller.log the pattern matches is compared with the robot's true pose when it
    was printed. A cell estimate's error is from its cell's centre; without a lattice (the
    course's own floor) cells are not judged."""
    errors, right = [], []
    for text, x, y in _printed_lines(run_dir):
        estimate = estimate_of(pattern, text)
        if estimate is None:
            continue
        if isinstance(estimate, tuple):
            point, cell = estimate, lattice.cell(*estimate) if lattice else None
        else:
            point, cell = (lattice.centre(estimate) if lattice else None), estimate
        errors.append(None if point is None else math.hypot(point[0] - x, point[1] - y))
        if lattice is not None:
            right.append(cell is not None and cell == lattice.cell(x, y))
    if not errors:
        return {"estimates": "0"}
    last = errors[-1]
    return {"estimates": str(len(errors)), "estimate_error_m": "" if last is None else f"{last:.3f}",
            "right_cell": f"{100.0 * sum(right) / len(right):.1f}%" if right else ""}
