"""The localization lab's updates on NumPy arrays, the same arithmetic as `maze_mapper demo
trilaterate` and `maze_mapper demo localize` (docs/lab-localization.md), so that a student's
own filter can be compared with the program's number by number.

Task 1's arena: 5 x 5 cells of 1 m, origin at the centre, x east, y north; cells numbered 1 to
25 row by row from the north-west; landmarks yellow (-2.5, 2.5), red (2.5, 2.5), green
(-2.5, -2.5), blue (2.5, -2.5).

Task 2's maze: `walls` is a bool array of shape (rows, columns, 4), row 0 the northern row,
column 0 the western one, the last axis the sides N, E, S, W; a belief has shape (rows,
columns), the same rows. A move or a side is 0 N, 1 E, 2 S, 3 W (or the letter).
"""

import math

import numpy as np

LANDMARKS = {"yellow": (-2.5, 2.5), "red": (2.5, 2.5), "green": (-2.5, -2.5), "blue": (2.5, -2.5)}
SENSOR = (0.8, 0.2, 0.4, 0.6)  # P(z=wall|wall), P(z=no wall|wall), P(z=wall|no wall), P(z=no wall|no wall)
SIDES = "NESW"


def trilaterate(points, distances):
    """(x, y, (A, B, C, D, E, F)) from three landmarks (x_i, y_i) and their distances r_i:
    circle 1 minus circle 2 gives A x + B y = C, circle 2 minus circle 3 D x + E y = F."""
    (x1, y1), (x2, y2), (x3, y3) = points
    r1, r2, r3 = distances
    a, b = 2 * (x2 - x1), 2 * (y2 - y1)
    c = r1 * r1 - r2 * r2 - x1 * x1 + x2 * x2 - y1 * y1 + y2 * y2
    d, e = 2 * (x3 - x2), 2 * (y3 - y2)
    f = r2 * r2 - r3 * r3 - x2 * x2 + x3 * x3 - y2 * y2 + y3 * y3
    x = (c * e - f * b) / (e * a - b * d)
    y = (c * d - a * f) / (b * d - a * e)
    return x, y, (a, b, c, d, e, f)


def arena_centres():
    """The 25 cell centres, shape (5, 5, 2), row 0 the northern row (cells 1 to 5)."""
    xs = -2.5 + np.arange(5) + 0.5
    ys = 2.5 - np.arange(5) - 0.5
    return np.stack(np.meshgrid(xs, ys), axis=-1)


def cell_scores(distances, sigma=1.0):
    """Each arena cell's score, shape (5, 5): the product over the landmarks with a distance
    (a dict name -> metres) of N(distance; the centre's distance to the landmark, sigma),
    normalised."""
    centres = arena_centres()
    scores = np.ones((5, 5))
    for name, z in distances.items():
        lx, ly = LANDMARKS[name]
        expected = np.hypot(centres[..., 0] - lx, centres[..., 1] - ly)
        scores *= np.exp(-0.5 * ((z - expected) / sigma) ** 2) / (sigma * math.sqrt(2 * math.pi))
    return scores / scores.sum()


def _side(side):
    return SIDES.index(side) if isinstance(side, str) else int(side)


def likelihood(walls, reading, sensor=SENSOR):
    """P(reading | cell) for every cell, shape (rows, columns); reading: four bools N, E, S, W."""
    p_ww, p_ow, p_wo, p_oo = sensor
    z = np.asarray(reading, dtype=bool)
    per_side = np.where(walls, np.where(z, p_ww, p_ow), np.where(z, p_wo, p_oo))
    return per_side.prod(axis=-1)


def correct(belief, walls, reading, sensor=SENSOR):
    """The belief times P(reading | cell), normalised."""
    posterior = belief * likelihood(walls, reading, sensor)
    return posterior / posterior.sum()


def predict(belief, walls, move, p_move=0.8):
    """A move towards `move`: from a cell open that way the robot arrives with p_move and
    stays with 1 - p_move; from a cell walled that way it stays."""
    s = _side(move)
    dr, dc = [(-1, 0), (0, 1), (1, 0), (0, -1)][s]
    blocked = walls[..., s]
    out = np.where(blocked, belief, (1 - p_move) * belief)
    moving = np.where(blocked, 0.0, p_move * belief)
    rows, cols = belief.shape
    for r in range(rows):
        for c in range(cols):
            if moving[r, c]:
                out[r + dr, c + dc] += moving[r, c]
    return out


def walls_from_text_map(text):
    """The walls of a micromouse text map (docs/formats.md), shape (rows, columns, 4)."""
    lines = [line for line in text.splitlines() if line[:1] in ("o", "+", "|", " ") and line.strip()]
    rows = (len(lines) - 1) // 2
    cols = (len(lines[0].rstrip()) - 1) // 4
    lines = [line.ljust(4 * cols + 1) for line in lines[:2 * rows + 1]]
    walls = np.zeros((rows, cols, 4), dtype=bool)
    for r in range(rows):
        for c in range(cols):
            walls[r, c, 0] = lines[2 * r][4 * c + 1] == "-"
            walls[r, c, 2] = lines[2 * r + 2][4 * c + 1] == "-"
            walls[r, c, 3] = lines[2 * r + 1][4 * c] == "|"
            walls[r, c, 1] = lines[2 * r + 1][4 * c + 4] == "|"
    return walls
