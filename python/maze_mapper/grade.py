"""python3 -m maze_mapper.grade WORLD FOLDER|FILE... [--cell-size M] [--csv FILE]
python3 -m maze_mapper.grade --controllers FOLDER [--world WORLD|own]... [--starts N] [--csv FILE]

Grades students' 4D grids against a world's truth, as `maze_mapper run` scores its own map:
one row a grid file (.npz with `grid` and optionally `visited` (n, 2) and `headings`, or a
bare .npy array), in name order, with coverage, wall accuracy and the first sides learned
wrong. A file that cannot be read or has the wrong shape is a row with its error. Exit
status: 0 when every file was graded, 1 when one could not be, 2 for a bad world or usage.

With --controllers, runs a class's controllers instead (one folder a student, as handed in):
each over every world and start (a world file's start positions 1 to N; on `own`, the course's
empty floor that the controller fills with its own load_environment, seeds 1 to N drawing the
course's random start), students in parallel, a student's runs one after another in the
controller's own folder, each under python3 -m maze_mapper.run with the time limits. One CSV
row a run: student, world, start, exit, end, simulated time, distance, collisions, final pose,
whether the goal was reached (where the world has one), and the map score (coverage, wall
accuracy) of the grid the controller kept (maze_mapper.keep_grid) or saved in its folder as
.npy/.npz during the run, on a maze world; then a table a line a student.
"""

import argparse
import concurrent.futures
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

import maze_mapper

_KEY = maze_mapper._native.report_key  # the summary keys, spelled once for every report


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
    return {"file": path, _KEY.coverage: f"{s.coverage_percent:.2f}%",
            _KEY.wall_accuracy: f"{s.wall_accuracy_percent:.2f}%", "wrong": str(len(s.wrong_sides)),
            "first_wrong": named, "error": ""}


GRID_COLUMNS = ["file", _KEY.coverage, _KEY.wall_accuracy, "wrong", "first_wrong", "error"]
RUN_COLUMNS = ["student", "world", "start", "exit", "end", "sim_time_s", "distance_m", "collisions", "final_x",
               "final_y", "final_yaw_deg", "goal", "grid", _KEY.coverage, _KEY.wall_accuracy, "error"]


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


def saved_grids(folder, since):
    """The .npy and .npz files the run wrote in the controller's folder (modified at or after
    `since`, a time.time()), in name order."""
    return sorted(os.path.join(folder, f) for f in os.listdir(folder)
                  if f.endswith((".npz", ".npy")) and os.path.getmtime(os.path.join(folder, f)) >= since)


def _text(mapping, key):
    value = mapping.get(key)
    return "" if value is None else str(value)


def _percent_text(summary, key):
    value = summary.get(key)
    return "" if value is None else f"{value:.2f}%"


def _summary_values(summary):
    """The row's columns from the run's summary.json."""
    pose = summary.get("final_pose") or {}
    kept = summary.get("grid") not in (None, "none")
    return {"end": _text(summary, "end"),
            "sim_time_s": f"{summary['sim_time_s']:.3f}" if summary.get("sim_time_s") is not None else "",
            "distance_m": _text(summary, "distance_m"), "collisions": _text(summary, "collisions"),
            "final_x": _text(pose, "x_m"), "final_y": _text(pose, "y_m"), "final_yaw_deg": _text(pose, "yaw_deg"),
            "goal": _text(summary, "goal"), "grid": "kept" if kept else "",
            _KEY.coverage: _percent_text(summary, _KEY.coverage),
            _KEY.wall_accuracy: _percent_text(summary, _KEY.wall_accuracy)}


def _score_saved_grid(row, truth, folder, since):
    """Where the controller kept no grid but saved one (.npy/.npz in its folder during the
    run), the row's map score is that file's against the world's truth."""
    if row.get("grid") or truth is None:
        return
    files = saved_grids(folder, since)
    if not files:
        return
    graded = grade(truth, files[0])
    row["grid"] = os.path.basename(files[0])
    if graded["error"]:
        row["error"] = row.get("error") or graded["error"]
    else:
        for key in (_KEY.coverage, _KEY.wall_accuracy):
            row[key] = graded[key]


def run_once(student, controller, world, start, args, truth=None):
    """One run under maze_mapper.run, in the controller's own folder, with --out into a
    temporary folder: its CSV row. On a world file, start N is the file's N-th start position;
    on `own`, seed N draws the course's random start."""
    row = {"student": student, "world": world, "start": start}
    folder = os.path.dirname(os.path.abspath(controller))
    with tempfile.TemporaryDirectory(prefix="maze_mapper_grade_") as out:
        command = [sys.executable, "-m", "maze_mapper.run", os.path.abspath(controller), "--seed", str(start),
                   "--time-limit", str(args.time_limit), "--wall-limit", str(args.wall_limit),
                   "--out", os.path.join(out, "run")]
        if world != "own":
            command += ["--world", os.path.abspath(world), "--start", f"pos:{start}"]
        since = time.time() - 1.0  # file times may be coarser than the clock
        try:
            done = subprocess.run(command, capture_output=True, text=True, timeout=args.wall_limit + 60,
                                  stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            return {**row, "exit": "", "end": "killed", "error": "no summary within the wall-clock limit"}
        summary_path = os.path.join(out, "run", "summary.json")
        summary = json.load(open(summary_path)) if os.path.isfile(summary_path) else {}
    errors = [line for line in done.stderr.splitlines()
              if line.strip() and not line.startswith(("wrote ", "note: "))]
    row = {**row, "exit": done.returncode, **_summary_values(summary),
           "error": errors[-1] if done.returncode != 0 and errors else ""}
    _score_saved_grid(row, truth, folder, since)
    return row


def _mean(values, form):
    return form.format(sum(values) / len(values)) if values else "-"


def _student_line(student, mine):
    finished = [r for r in mine if r.get("exit") == 0]
    with_goal = [r for r in mine if r.get("goal")]
    reached = sum(1 for r in with_goal if r["goal"] == "reached")
    failed = [r for r in mine if r.get("exit") != 0]
    return [student, f"{len(finished)}/{len(mine)}", f"{reached}/{len(with_goal)}" if with_goal else "-",
            _mean([float(r["sim_time_s"]) for r in finished if r.get("sim_time_s")], "{:.1f} s"),
            *(_mean([float(r[key].rstrip("%")) for r in mine if r.get(key)], "{:.1f}%")
              for key in (_KEY.coverage, _KEY.wall_accuracy)),
            str(sum(int(r["collisions"]) for r in mine if r.get("collisions"))),
            f"{failed[0]['world']}, start {failed[0]['start']}: {failed[0].get('error') or failed[0].get('end')}"
            if failed else ""]


def class_summary(rows):
    """A table a teacher reads, a line a student: runs finished, goals reached (of the runs
    whose world has a goal), mean simulated time of the finished runs, mean map scores, the
    collisions, and the first failed run with its reason."""
    header = ["student", "finished", "goal reached", "mean time", "coverage", "wall accuracy", "collisions",
              "first failure"]
    table = [header] + [_student_line(s, [r for r in rows if r["student"] == s])
                        for s in sorted({r["student"] for r in rows})]
    widths = [max(len(line[i]) for line in table) for i in range(len(header) - 1)]
    return ["  ".join([cell.ljust(widths[i]) if i == 0 else cell.rjust(widths[i])
                       for i, cell in enumerate(line[:-1])] + [line[-1]]).rstrip() for line in table]


def _truth(world):
    """The world's maze, to score the grids the controllers save, read as the runner reads it;
    None for `own`, an arena (no lattice to score a grid on) or a file the runs will refuse."""
    if world == "own":
        return None
    try:
        read = maze_mapper.load_world(world)
    except maze_mapper.Error:
        return None
    return read if read.is_maze else None


def _student_runs(student, controller, worlds, args, truths):
    """A student's runs, one after another (a run may save its grid in the student's folder)."""
    return [run_once(student, controller, w, s, args, truths[w]) for w in worlds for s in range(1, args.starts + 1)]


def class_main(argv):
    p = _Parser(prog="python3 -m maze_mapper.grade --controllers",
                description="Run a class's controllers over worlds and starts; one CSV row a run.")
    p.add_argument("--controllers", required=True, help="a folder holding one folder a student, as handed in")
    p.add_argument("--controller", help="the controller's file name in each student's folder")
    p.add_argument("--world", action="append", default=[],
                   help="a world file (repeatable); own: the controller loads its own (default)")
    p.add_argument("--starts", type=int, default=1,
                   help="runs a world: a world file's start positions 1 to N, or on `own` seeds 1 to N (default 1)")
    p.add_argument("--time-limit", type=float, default=300.0, help="simulated seconds a run (default 300)")
    p.add_argument("--wall-limit", type=float, default=120.0, help="wall-clock seconds a run (default 120)")
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="students run at once (default: the cores)")
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
    truths = {w: _truth(w) for w in worlds}
    students, rows = [], []
    for student in sorted(os.listdir(args.controllers)):
        folder = os.path.join(args.controllers, student)
        if not os.path.isdir(folder):
            continue
        try:
            students.append((student, student_controller(folder, args.controller)))
        except ValueError as e:
            rows += [{"student": student, "world": w, "start": s, "end": "not run", "error": str(e)}
                     for w in worlds for s in range(1, args.starts + 1)]
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for runs in pool.map(lambda sc: _student_runs(*sc, worlds, args, truths), students):
            rows += runs
    rows.sort(key=lambda r: (r["student"], worlds.index(r["world"]), r["start"]))
    write_csv(args.csv, rows, RUN_COLUMNS)
    for line in class_summary(rows):
        print(line)
    finished = sum(1 for r in rows if r.get("exit") == 0)
    reached = sum(1 for r in rows if r.get("goal") == "reached")
    print(f"total: {len(rows)} runs, {finished} finished, {reached} reached the goal; rows in {args.csv}")
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
