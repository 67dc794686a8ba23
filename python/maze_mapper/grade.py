"""python3 -m maze_mapper.grade WORLD FOLDER|FILE... [--subcells K] [--csv FILE]

Grades students' 4D grids against a world's truth, as `maze_mapper run` scores its own map:
one row a grid file (.npz with `grid` and optionally `visited` (n, 2) and `headings`, or a
bare .npy array), in name order, with coverage, wall accuracy and the first sides learned
wrong. A file that cannot be read or has the wrong shape is a row with its error. Exit
status: 0 when every file was graded, 1 when one could not be, 2 for a bad world or usage.
"""

import argparse
import csv
import os
import sys
import tempfile

import maze_mapper


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        print(f"error: {message}", file=sys.stderr)
        sys.exit(2)


def grid_files(paths):
    files = []
    for path in paths:
        if os.path.isdir(path):
            files += sorted(os.path.join(path, f) for f in os.listdir(path) if f.endswith((".npz", ".npy")))
        else:
            files.append(path)
    return files


def read_grid(path):
    """(grid, visited) from a .npz or .npy file; raises maze_mapper.Error when unreadable."""
    import numpy as np
    try:
        data = np.load(path, allow_pickle=False)
    except (OSError, ValueError) as e:
        raise maze_mapper.Error(f"{path}: error: cannot read it as a NumPy file ({e})") from None
    if not hasattr(data, "files"):
        return data, None
    if "grid" not in data.files:
        raise maze_mapper.Error(f"{path}: error: no array named grid in it (found: {', '.join(data.files)})")
    visited = None
    if "visited" in data.files:
        headings = data["headings"] if "headings" in data.files else ["N"] * len(data["visited"])
        visited = {(int(x), int(y)): str(h) for (x, y), h in zip(data["visited"], headings)}
    return data["grid"], visited


def grade(world, path):
    """One row: file, coverage, wall_accuracy, wrong (count), first wrong sides, error."""
    try:
        grid, visited = read_grid(path)
        s = maze_mapper.score(world, grid, visited)
    except maze_mapper.Error as e:
        message = str(e)
        return {"file": path, "error": message if message.startswith(path) else f"{path}: {message}"}
    named = "; ".join(repr(w) for w in s.wrong_sides[:3]) + ("; ..." if len(s.wrong_sides) > 3 else "")
    return {"file": path, "coverage": f"{s.coverage_percent:.2f}%",
            "wall_accuracy": f"{s.wall_accuracy_percent:.2f}%", "wrong": str(len(s.wrong_sides)),
            "first_wrong": named, "error": ""}


def write_csv(path, rows):
    """The rows as CSV, written whole or not at all (a temporary file renamed over it)."""
    directory = os.path.dirname(os.path.abspath(path))
    with tempfile.NamedTemporaryFile("w", newline="", dir=directory, delete=False, suffix=".tmp") as out:
        try:
            writer = csv.DictWriter(out, ["file", "coverage", "wall_accuracy", "wrong", "first_wrong", "error"])
            writer.writeheader()
            writer.writerows(rows)
        except BaseException:
            os.unlink(out.name)
            raise
    os.replace(out.name, path)


def main(argv=None):
    p = _Parser(prog="python3 -m maze_mapper.grade", description="Grade students' 4D grids against a world.")
    p.add_argument("world", help="the maze the students mapped (any format)")
    p.add_argument("grids", nargs="+", help="grid files (.npz, .npy), or folders of them")
    p.add_argument("--cell-size", type=float, help="cell size in m of a text or num world")
    p.add_argument("--csv", help="also write the rows to this CSV file")
    args = p.parse_args(argv)
    try:
        world = maze_mapper.load_world(args.world, cell_size_m=args.cell_size)
    except maze_mapper.Error as e:
        print(e, file=sys.stderr)
        return 2
    files = grid_files(args.grids)
    if not files:
        p.error(f"no .npz or .npy files in {' '.join(args.grids)}")
    rows = [grade(world, f) for f in files]
    width = max(len(r["file"]) for r in rows)
    print(f"{'file':<{width}}  {'coverage':>8}  {'wall_accuracy':>13}  {'wrong':>5}  first wrong sides")
    for r in rows:
        if r["error"]:
            print(f"{r['file']:<{width}}  {'-':>8}  {'-':>13}  {'-':>5}  {r['error']}")
        else:
            print(f"{r['file']:<{width}}  {r['coverage']:>8}  {r['wall_accuracy']:>13}  {r['wrong']:>5}  {r['first_wrong']}")
    failed = sum(1 for r in rows if r["error"])
    print(f"total: {len(rows)} grids, {len(rows) - failed} graded, {failed} failed")
    if args.csv:
        write_csv(args.csv, rows)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
