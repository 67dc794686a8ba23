"""python3 -m maze_mapper.grade WORLD FOLDER|FILE... [--cell-size M] [--csv FILE]
python3 -m maze_mapper.grade --controllers FOLDER [--world WORLD|own]... [--starts N] [--csv FILE]

Grades students' 4D grids against a world's truth, as `maze_mapper run` scores its own map:
one row a grid file (.npz with `grid` and optionally `visited` (n, 2) and `headings`, or a
bare .npy array), in name order, with coverage, wall accuracy and the first sides learned
wrong. A file that cannot be read or has the wrong shape is a row with its error. Exit
status: 0 when every file was graded, 1 when one could not be, 2 for a bad world or usage.

With --controllers, runs a class's controllers instead (one folder a student, as handed in):
each over every world (`own`: the course's empty floor, which the controller fills with its
own load_environment) and start (seeds 1 to N: the course's random start and the sensors'
noise), in parallel, each under python3 -m maze_mapper.run with the time limits; one CSV row a
run (student, world, start, exit, end, simulated time, distance, collisions, final pose, and
coverage and wall accuracy where the controller kept a grid), and a summary a student a line.
"""

import argparse
import concurrent.futures
import csv
import os
import subprocess
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


GRID_COLUMNS = ["file", "coverage", "wall_accuracy", "wrong", "first_wrong", "error"]
RUN_COLUMNS = ["student", "world", "start", "exit", "end", "sim_time_s", "distance_m", "collisions", "final_x",
               "final_y", "final_yaw_deg", "coverage", "wall_accuracy", "error"]


def write_csv(path, rows, columns=GRID_COLUMNS):
    """The rows as CSV, written whole or not at all (a temporary file renamed over it)."""
    directory = os.path.dirname(os.path.abspath(path))
    with tempfile.NamedTemporaryFile("w", newline="", dir=directory, delete=False, suffix=".tmp") as out:
        try:
            writer = csv.DictWriter(out, columns)
            writer.writeheader()
            writer.writerows(rows)
        except BaseException:
            os.unlink(out.name)
            raise
    os.replace(out.name, path)


def student_controller(folder, name):
    """The controller file in a student's folder: NAME when given, else the folder's only .py
    file, else FOLDER_NAME.py (Webots' rule); raises ValueError saying which is missing."""
    if name:
        path = os.path.join(folder, name)
        if not os.path.isfile(path):
            raise ValueError(f"no {name} in {folder}")
        return path
    scripts = sorted(f for f in os.listdir(folder) if f.endswith(".py"))
    if len(scripts) == 1:
        return os.path.join(folder, scripts[0])
    own = os.path.basename(os.path.normpath(folder)) + ".py"
    if own in scripts:
        return os.path.join(folder, own)
    raise ValueError(f"{folder}: {len(scripts)} .py files and none named {own} (--controller NAME chooses)")


def run_once(student, controller, world, start, args):
    """One run under maze_mapper.run: its CSV row."""
    row = {"student": student, "world": world, "start": start}
    command = [sys.executable, "-m", "maze_mapper.run", os.path.abspath(controller), "--seed", str(start),
               "--time-limit", str(args.time_limit), "--wall-limit", str(args.wall_limit)]
    if world != "own":
        command += ["--world", os.path.abspath(world)]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=args.wall_limit + 60,
                              stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return {**row, "exit": "", "end": "killed", "error": "no summary within the wall-clock limit"}
    summary = {}
    block = done.stdout.rstrip("\n").split("\n\n")[-1]
    for line in block.splitlines():
        key, _, value = line.partition(": ")
        summary[key] = value
    x, y, yaw = (summary.get("final_pose", "") + "  ").split(" ")[:3]
    errors = [line for line in done.stderr.splitlines() if line.strip()]
    return {**row, "exit": done.returncode, "end": summary.get("end", ""), "sim_time_s": summary.get("sim_time_s", ""),
            "distance_m": summary.get("distance_m", ""), "collisions": summary.get("collisions", ""), "final_x": x, "final_y": y, "final_yaw_deg": yaw,
            "coverage": summary.get("coverage", ""), "wall_accuracy": summary.get("wall_accuracy", ""),
            "error": errors[-1] if done.returncode != 0 and errors else ""}


def class_summary(rows):
    """A line a student: runs, finished runs, mean simulated time and coverage."""
    lines = []
    for student in sorted({r["student"] for r in rows}):
        mine = [r for r in rows if r["student"] == student]
        finished = [r for r in mine if r.get("exit") == 0]
        times = [float(r["sim_time_s"]) for r in finished if r.get("sim_time_s")]
        coverage = [float(r["coverage"].rstrip("%")) for r in finished if r.get("coverage")]
        line = f"{student}: {len(finished)}/{len(mine)} runs finished"
        if times:
            line += f", mean {sum(times) / len(times):.1f} s simulated"
        if coverage:
            line += f", mean coverage {sum(coverage) / len(coverage):.1f}%"
        failed = [r for r in mine if r.get("exit") != 0]
        if failed:
            line += f"; first failure ({failed[0]['world']}, start {failed[0]['start']}): {failed[0].get('error') or failed[0].get('end')}"
        lines.append(line)
    return lines


def class_main(argv):
    p = _Parser(prog="python3 -m maze_mapper.grade --controllers",
                description="Run a class's controllers over worlds and starts; one CSV row a run.")
    p.add_argument("--controllers", required=True, help="a folder holding one folder a student, as handed in")
    p.add_argument("--controller", help="the controller's file name in each student's folder")
    p.add_argument("--world", action="append", default=[],
                   help="a world file (repeatable); own: the controller loads its own (default)")
    p.add_argument("--starts", type=int, default=1, help="runs a world, seeds 1 to N (default 1)")
    p.add_argument("--time-limit", type=float, default=300.0, help="simulated seconds a run (default 300)")
    p.add_argument("--wall-limit", type=float, default=120.0, help="wall-clock seconds a run (default 120)")
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="runs at once (default: the cores)")
    p.add_argument("--csv", default="grades.csv", help="the rows' CSV file (default grades.csv)")
    args = p.parse_args(argv)
    if not os.path.isdir(args.controllers):
        p.error(f"cannot read {args.controllers}: not a folder")
    if args.starts < 1 or args.jobs < 1 or not args.time_limit > 0 or not args.wall_limit > 0:
        p.error("--starts and --jobs must be at least 1, the limits above 0")
    worlds = args.world or ["own"]
    for w in worlds:
        if w != "own" and not os.path.isfile(w):
            p.error(f"cannot read {w}: no such file")
    runs, rows = [], []
    for student in sorted(os.listdir(args.controllers)):
        folder = os.path.join(args.controllers, student)
        if not os.path.isdir(folder):
            continue
        try:
            controller = student_controller(folder, args.controller)
        except ValueError as e:
            rows += [{"student": student, "world": w, "start": s, "end": "not run", "error": str(e)}
                     for w in worlds for s in range(1, args.starts + 1)]
            continue
        runs += [(student, controller, w, s) for w in worlds for s in range(1, args.starts + 1)]
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        rows += list(pool.map(lambda run: run_once(*run, args), runs))
    rows.sort(key=lambda r: (r["student"], r["world"], r["start"]))
    write_csv(args.csv, rows, RUN_COLUMNS)
    for line in class_summary(rows):
        print(line)
    print(f"total: {len(rows)} runs, {sum(1 for r in rows if r.get('exit') == 0)} finished; rows in {args.csv}")
    return 0


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if any(a == "--controllers" or a.startswith("--controllers=") for a in argv):
        return class_main(argv)
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
