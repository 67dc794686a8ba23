"""Checks a student's 4D grid against a world's truth: prints the grid as the lab prints its
map, then the score and every side it got wrong.

    python3 python/examples/check_grid.py WORLD [GRID.npz]

GRID.npz holds `grid` (rows x columns x K x K log-odds, grid[y, x, i, j] with y from the south
and i from the north), and optionally `visited` ((n, 2) cells x, y) and `headings` (n of
"N", "E", "S", "W"), as lab_mapper.py's --save-grid writes them. Without GRID.npz, a grid is
made by hand from the truth, the way a student fills one in, with two mistakes.
"""

import math
import sys

import numpy as np

import maze_mapper

L_OCC, L_FREE = math.log(0.6 / 0.4), math.log(0.3 / 0.7)


def hand_made(world, k=3):
    """Every cell's bands from the truth, the lab's way (a wall: the whole band; an opening:
    the band's middle), then two mistakes: (0,0)'s east side and the last cell's north band."""
    grid = np.zeros((world.height, world.width, k, k))
    m = k // 2
    for y in range(world.height):
        for x in range(world.width):
            cell = grid[y, x]
            cell[m, m] = L_FREE
            for side, band in (("N", (0, slice(None))), ("S", (k - 1, slice(None))),
                               ("W", (slice(None), 0)), ("E", (slice(None), k - 1))):
                if world.has_wall(x, y, side):
                    cell[band] = L_OCC
                else:
                    middle = {"N": (0, m), "S": (k - 1, m), "W": (m, 0), "E": (m, k - 1)}[side]
                    cell[middle] = L_FREE
    east = grid[0, 0, m, k - 1]
    grid[0, 0, m, k - 1] = L_FREE if east > 0 else L_OCC
    grid[-1, -1, 0, :] = 0.0  # never observed
    visited = {(x, y): "N" for y in range(world.height) for x in range(world.width)}
    return grid, visited


def load(path):
    data = np.load(path)
    visited = {}
    if "visited" in data:
        headings = data["headings"] if "headings" in data else ["N"] * len(data["visited"])
        visited = {(int(x), int(y)): str(h) for (x, y), h in zip(data["visited"], headings)}
    return data["grid"], visited


def main(argv):
    if len(argv) not in (2, 3):
        print(__doc__.strip().splitlines()[3].strip(), file=sys.stderr)
        return 2
    try:
        world = maze_mapper.load_world(argv[1])
        grid, visited = load(argv[2]) if len(argv) == 3 else hand_made(world)
        text = maze_mapper.render(grid, visited)
        score = maze_mapper.score(world, grid, visited)
    except maze_mapper.Error as e:
        print(e, file=sys.stderr)
        return 2
    print(text)
    print(f"coverage: {score.coverage_percent:.2f}%")
    print(f"wall_accuracy: {score.wall_accuracy_percent:.2f}% "
          f"({score.sides_correct} of {score.sides} sides)")
    for side in score.wrong_sides:
        print(f"wrong: {side!r}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
