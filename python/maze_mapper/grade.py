"""python3 -m maze_mapper.grade WORLD FOLDER|FILE... [--cell-size M] [--csv FILE]
python3 -m maze_mapper.grade --controllers FOLDER [--world WORLD|own]... [--starts N]
    [--goal landmark|COLOR] [--estimate REGEX] [--keys FILE] [--keep DIR] [--csv FILE] [--shard K/N]
python3 -m maze_mapper.grade --merge PART.csv... [--csv FILE]

Grades students' 4D grids against a world's truth, as `maze_mapper run` scores its own map:
one row a grid file (.npz with `grid` and optionally `visited` (n, 2) and `headings`, or a
bare .npy array), in name order, with coverage, wall accuracy and the first sides learned
wrong. A file that cannot be read or has the wrong shape is a row with its error. Exit
status: 0 when every file was graded, 1 when one could not be, 2 for a bad world or usage.

With --controllers, runs a class's controllers instead (one folder a student, as handed in):
each over every world and start (a world file's start positions 1 to N; on `own`, the course's
empty floor that the controller fills with its own load_environment, the seeds whose draw
takes the course's starts 1 to N), students in parallel, a student's runs one after another in
the controller's own folder, each under python3 -m maze_mapper.run with the time limits. One
row a run: student, world, start, seed, result (finished, timed out, crashed, ...), exit, end,
simulated time, distance, collisions, final pose, whether the goal was reached (the world's,
or with --goal a landmark's), the position estimates the controller printed (--estimate), and
the map score (coverage, wall accuracy) of the grid the controller kept
(maze_mapper.keep_grid) or saved in its folder as .npy/.npz during the run, on a maze world;
then a table a line a student. --keys FILE hands the runner's --keys FILE (a script of timed
keys for the Keyboard) to every run, for a teleoperation lab. Files only where asked: --csv FILE the rows, --keep DIR each
run's folder. --shard K/N runs the K-th of N contiguous parts of the runs (students x worlds
x starts, in that order), as `maze_mapper batch --shard` cuts its worlds, for a job array;
--merge joins the parts' CSVs and prints the table the whole class's run prints. Exit status:
0 when every run finished, 1 when one did not, 2 for usage.
"""

import argparse
import concurrent.futures
import csv
import json
import os
import random
import re
import subprocess
import sys
import tempfile
import time

import maze_mapper
from maze_mapper import _lab_scores, keyboard

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
RUN_COLUMNS = ["student", "world", "start", "seed", "result", "exit", "end", "sim_time_s", "distance_m", "collisions",
               "final_x", "final_y", "final_yaw_deg", "goal", "landmark_gap_m", "estimates", "estimate_error_m",
               "right_cell", "grid", _KEY.coverage, _KEY.wall_accuracy, "error"]
# The ends of a run the simulation's limits made: the controller did not finish in time.
_TIMED_OUT = ("time limit", "max steps", "wall-clock limit")


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


def own_start_seed(start, starts):
    """The seed of start `start` (1 to `starts`) on the course's own floor: the first seed from 1
    up whose draw of one of `starts` start positions, as the course's move_to_start draws it
    (random.sample), takes the start-th; so N runs of a world with N starts run each once."""
    seed = 1
    while random.Random(seed).sample(range(starts), 1)[0] != start - 1:
        seed += 1
    return seed


def _run_dir(keep, student, world, start):
    """Where a run's --out goes when the runs are kept: KEEP/STUDENT/WORLD-START."""
    name = "own" if world == "own" else os.path.splitext(os.path.basename(world))[0]
    return os.path.join(keep, student, f"{name}-{start}")


def _result(row):
    """finished, timed out (a limit of the simulation ended it), crashed, or how else it ended."""
    if row.get("exit") == 0:
        return "timed out" if row.get("end") in _TIMED_OUT else "finished"
    if row.get("end") == "controller failed":
        return "crashed"
    return row.get("end") or "failed"


def _lab_values(row, summary, out, args, lattice):
    """The Lab 3 goal (--goal: the body stopped within --goal-distance of a landmark) and the
    Lab 4 estimates (--estimate) of a run, into its row."""
    if args.goal:
        gap = _lab_scores.landmark_gap(summary, args.goal)
        row["landmark_gap_m"] = "" if gap is None else f"{gap:.3f}"
        row["goal"] = "" if gap is None else (
            "reached" if gap <= args.goal_distance and row["result"] == "finished" else "not reached")
    if args.estimate:
        row.update(_lab_scores.estimate_scores(out, args.estimate, lattice))


def run_once(student, controller, world, start, args, truth=None):
    """One run under maze_mapper.run, in the controller's own folder, with --out into
    --keep's folder for it or a temporary one: its CSV row. On a world file, start N is the
    file's N-th start position; on `own`, the seed drawing the course's N-th start."""
    seed = start if world != "own" else own_start_seed(start, args.starts)
    row = {"student": student, "world": world, "start": start, "seed": seed}
    folder = os.path.dirname(os.path.abspath(controller))
    with tempfile.TemporaryDirectory(prefix="maze_mapper_grade_") as scratch:
        out = _run_dir(args.keep, student, world, start) if args.keep else os.path.join(scratch, "run")
        command = [sys.executable, "-m", "maze_mapper.run", os.path.abspath(controller), "--seed", str(seed),
                   "--time-limit", str(args.time_limit), "--wall-limit", str(args.wall_limit),
                   "--out", os.path.abspath(out)]
        if args.keys is not None:
            command += ["--keys", args.keys]
        if world != "own":
            command += ["--world", os.path.abspath(world), "--start", f"pos:{start}"]
        since = time.time() - 1.0  # file times may be coarser than the clock
        try:
            done = subprocess.run(command, capture_output=True, text=True, timeout=args.wall_limit + 60,
                                  stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            return {**row, "result": "killed", "exit": "", "end": "killed",
                    "error": "no summary within the wall-clock limit"}
        summary_path = os.path.join(out, "summary.json")
        summary = json.load(open(summary_path)) if os.path.isfile(summary_path) else {}
        errors = [line for line in done.stderr.splitlines()
                  if line.strip() and not line.startswith(("wrote ", "note: "))]
        row = {**row, "exit": done.returncode, **_summary_values(summary),
               "error": errors[-1] if done.returncode != 0 and errors else ""}
        row["result"] = _result(row)
        lattice = args.lattices.get(world)
        if world == "own" and summary.get("walls_extent_m"):  # the floor the controller's walls enclose
            lattice = _lab_scores.Lattice.of_boundary(summary["walls_extent_m"], args.cell_size)
        _lab_values(row, summary, out, args, lattice)
    _score_saved_grid(row, truth, folder, since)
    return row


def _mean(values, form):
    return form.format(sum(values) / len(values)) if values else "-"


def _count(mine, result):
    return str(sum(1 for r in mine if r.get("result") == result))


def _student_line(student, mine, estimates):
    finished = [r for r in mine if r.get("result") == "finished"]
    with_goal = [r for r in mine if r.get("goal")]
    reached = sum(1 for r in with_goal if r["goal"] == "reached")
    failed = [r for r in mine if r.get("result") != "finished"]
    line = [student, f"{len(finished)}/{len(mine)}", _count(mine, "timed out"), _count(mine, "crashed"),
            f"{reached}/{len(with_goal)}" if with_goal else "-"]
    if estimates:
        line += [_mean([float(r["estimate_error_m"]) for r in mine if r.get("estimate_error_m")], "{:.2f} m"),
                 _mean([float(r["right_cell"].rstrip("%")) for r in mine if r.get("right_cell")], "{:.0f}%")]
    first = failed[0] if failed else None
    if first:
        reason = first.get("error") or (first.get("end") if first.get("end") != first["result"] else "")
        first = f"{first['world']}, start {first['start']}: {first['result']}{': ' + reason if reason else ''}"
    return line + [
        _mean([float(r["sim_time_s"]) for r in finished if r.get("sim_time_s")], "{:.1f} s"),
        *(_mean([float(r[key].rstrip("%")) for r in mine if r.get(key)], "{:.1f}%")
          for key in (_KEY.coverage, _KEY.wall_accuracy)),
        str(sum(int(r["collisions"]) for r in mine if r.get("collisions"))),
        first or ""]


def class_summary(rows, estimates=False):
    """A table a teacher reads, a line a student: runs finished (ended by the controller with
    status 0), timed out and crashed, goals reached (of the runs whose world or --goal has
    one), with --estimate the mean of the runs' last estimate errors and of their shares of
    estimates in the right cell, the mean simulated time of the finished runs, mean map scores,
    the collisions, and the first run not finished with its reason."""
    header = ["student", "finished", "timed out", "crashed", "goal reached"]
    if estimates:
        header += ["last estimate error", "right cell"]
    header += ["mean time", "coverage", "wall accuracy", "collisions", "first failure"]
    table = [header] + [_student_line(s, [r for r in rows if r["student"] == s], estimates)
                        for s in sorted({r["student"] for r in rows})]
    widths = [max(len(line[i]) for line in table) for i in range(len(header) - 1)]
    return ["  ".join([cell.ljust(widths[i]) if i == 0 else cell.rjust(widths[i])
                       for i, cell in enumerate(line[:-1])] + [line[-1]]).rstrip() for line in table]


def _read_world(world):
    if world == "own":
        return None
    try:
        return maze_mapper.load_world(world)
    except maze_mapper.Error:
        return None


def _student_runs(student, controller, runs, args, truths):
    """A student's runs ((world, start) pairs), one after another (a run may save its grid in
    the student's folder)."""
    return [run_once(student, controller, w, s, args, truths[w]) for w, s in runs]


def parse_shard(text):
    """(K, N) from "K/N" with 1 <= K <= N, as `maze_mapper batch --shard` takes it; else None."""
    match = re.fullmatch(r"([1-9][0-9]*)/([1-9][0-9]*)", text)
    if match is None or int(match.group(1)) > int(match.group(2)):
        return None
    return int(match.group(1)), int(match.group(2))


def shard_of(items, shard):
    """The K-th of N contiguous, near-equal parts of items, as `batch --shard` cuts its worlds:
    parts 1 to N together are the list, in order."""
    k, n = shard
    return items[len(items) * (k - 1) // n:len(items) * k // n]


CLASS_USAGE = ("python3 -m maze_mapper.grade --controllers FOLDER [--world WORLD|own]... [--starts N] "
               "[--goal landmark|COLOR] [--estimate REGEX] [--keys FILE] [--keep DIR] [--csv FILE] [--shard K/N]")
MERGE_USAGE = "python3 -m maze_mapper.grade --merge PART.csv... [--csv FILE]"


def _class_parser():
    p = _Parser(prog="python3 -m maze_mapper.grade --controllers", usage=CLASS_USAGE,
                description="Run a class's controllers over worlds and starts; one CSV row a run.")
    p.add_argument("--controllers", required=True, help="a folder holding one folder a student, as handed in")
    p.add_argument("--controller", help="the controller's file name in each student's folder")
    p.add_argument("--world", action="append", default=[],
                   help="a world file (repeatable); own: the controller loads its own (default)")
    p.add_argument("--starts", type=int, default=1,
                   help="runs a world: a world file's start positions 1 to N, or on `own` the course's N starts "
                        "(default 1)")
    p.add_argument("--time-limit", type=float, default=300.0, help="simulated seconds a run (default 300)")
    p.add_argument("--wall-limit", type=float, default=120.0, help="wall-clock seconds a run (default 120)")
    p.add_argument("--goal", choices=_lab_scores.goal_targets(), metavar="landmark|COLOR",
                   help="the goal is to stop near a landmark (any, or of this colour: "
                        f"{', '.join(_lab_scores.COLORS)}): reached when the run finished with the robot's body "
                        "within --goal-distance of the landmark's surface")
    p.add_argument("--goal-distance", type=float, default=0.5, metavar="M",
                   help="metres between body and landmark that count as reached (default 0.5)")
    p.add_argument("--estimate", metavar="REGEX",
                   help="lines the controller prints that match are position estimates: groups x and y "
                        "(metres) or cell (the course's number, row by row from the north-west, 1 to N); "
                        "unnamed, two numbers are x and y, one a cell")
    p.add_argument("--cell-size", type=float, default=1.0, metavar="M",
                   help="the cells of an arena world that --estimate numbers (default 1, the course's); "
                        "a maze's are its own")
    p.add_argument("--keys", metavar="FILE",
                   help="every run's keyboard keys from this script of timed keys (the runner's --keys FILE)")
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="students run at once (default: the cores)")
    p.add_argument("--keep", metavar="DIR",
                   help="keep each run's folder (summary, pictures, replay, controller.log) as DIR/STUDENT/WORLD-START")
    p.add_argument("--csv", help="also write the rows to this CSV file")
    p.add_argument("--shard", metavar="K/N",
                   help="run the K-th of N contiguous parts of the runs (students x worlds x starts, in order), "
                        "as batch --shard; --merge joins the parts' CSVs")
    return p


def _class_args(argv):
    p = _class_parser()
    args = p.parse_args(argv)
    if not os.path.isdir(args.controllers):
        p.error(f"cannot read {args.controllers}: not a folder")
    if args.starts < 1 or args.jobs < 1 or not args.time_limit > 0 or not args.wall_limit > 0:
        p.error("--starts and --jobs must be at least 1, the limits above 0")
    if not args.goal_distance >= 0 or not args.cell_size > 0:
        p.error("--goal-distance must be 0 or more, --cell-size above 0")
    if args.estimate is not None:
        try:
            args.estimate = re.compile(args.estimate)
        except re.error as e:
            p.error(f"--estimate {args.estimate}: not a regular expression ({e})")
    if args.keys is not None:
        try:
            keyboard.read_key_script(args.keys)  # its errors once, here, not in every run
        except keyboard.KeyScriptError as e:
            print(e, file=sys.stderr)
            sys.exit(2)
        args.keys = os.path.abspath(args.keys)  # runs start in the controllers' folders
    args.worlds = args.world or ["own"]
    for w in args.worlds:
        if w != "own" and not os.path.isfile(w):
            p.error(f"cannot read {w}: no such file")
    if args.keep is not None and os.path.exists(args.keep) and not os.path.isdir(args.keep):
        p.error(f"--keep {args.keep}: not a folder")
    if args.shard is not None:
        text, args.shard = args.shard, parse_shard(args.shard)
        if args.shard is None:
            p.error(f"--shard must be K/N with 1 <= K <= N, e.g. 2/8 (got '{text}')")
        if not args.csv:
            p.error("--shard needs --csv FILE (the part's rows, which --merge joins)")
    return args


def class_main(argv):
    args = _class_args(argv)
    worlds = args.worlds
    read = {w: _read_world(w) for w in worlds}
    truths = {w: r if r is not None and r.is_maze else None for w, r in read.items()}  # to score saved grids
    args.lattices = {w: None if r is None else _lab_scores.Lattice.of_world(r, args.cell_size) for w, r in read.items()}
    every = [(student, w, s) for student in sorted(os.listdir(args.controllers))
             if os.path.isdir(os.path.join(args.controllers, student)) for w in worlds for s in range(1, args.starts + 1)]
    mine = shard_of(every, args.shard) if args.shard else every
    if args.shard and not mine:
        print(f"warning: --shard {args.shard[0]}/{args.shard[1]}: no runs in this part ({len(every)} in all)",
              file=sys.stderr)
    students, rows = [], []
    for student in sorted({s for s, _, _ in mine}):
        runs = [(w, k) for s, w, k in mine if s == student]
        try:
            students.append((student, student_controller(os.path.join(args.controllers, student), args.controller),
                             runs))
        except ValueError as e:
            rows += [{"student": student, "world": w, "start": k, "result": "not run", "end": "not run",
                      "error": str(e)} for w, k in runs]
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for runs in pool.map(lambda scr: _student_runs(*scr, args, truths), students):
            rows += runs
    rows.sort(key=lambda r: (r["student"], worlds.index(r["world"]), r["start"]))
    if args.csv:
        write_csv(args.csv, rows, RUN_COLUMNS)
    return _report_class(rows, args.estimate is not None, args.csv, args.keep)


def _report_class(rows, estimates, csv_path, keep):
    """Prints the table and the totals line; the exit status: 0 when every run finished."""
    for line in class_summary(rows, estimates=estimates):
        print(line)
    finished = sum(1 for r in rows if r.get("result") == "finished")
    reached = sum(1 for r in rows if r.get("goal") == "reached")
    where = f"; rows in {csv_path}" if csv_path else ""
    kept = f"; runs kept in {keep}" if keep else ""
    print(f"total: {len(rows)} runs, {finished} finished, {reached} reached the goal{where}{kept}")
    return 0 if finished == len(rows) else 1


def merge_main(argv):
    """--merge PART.csv... [--csv FILE]: the parts' rows (--shard's CSVs) in the order given,
    and the table and totals one run of the whole class prints."""
    p = _Parser(prog="python3 -m maze_mapper.grade --merge",
                description="Join the CSVs of grade --controllers --shard parts; print the class's table.")
    p.add_argument("--merge", nargs="+", required=True, metavar="PART.csv", help="the parts' CSVs, part 1 first")
    p.add_argument("--csv", help="also write the joined rows to this CSV file")
    args = p.parse_args(argv)
    rows = []
    for path in args.merge:
        try:
            with open(path, newline="") as f:
                reader = csv.DictReader(f)
                if reader.fieldnames != RUN_COLUMNS:
                    p.error(f"{path}: not the CSV of a grade --controllers run (its columns differ)")
                rows += list(reader)
        except OSError as e:
            p.error(f"cannot read {path}: {e.strerror}")
    if args.csv:
        write_csv(args.csv, rows, RUN_COLUMNS)
    return _report_class(rows, any(r.get("estimates") for r in rows), args.csv, None)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if any(a == "--controllers" or a.startswith("--controllers=") for a in argv):
        return class_main(argv)
    if any(a == "--merge" for a in argv):
        return merge_main(argv)
    p = _Parser(prog="python3 -m maze_mapper.grade",
                usage="python3 -m maze_mapper.grade WORLD FOLDER|FILE... [--cell-size M] [--csv FILE]\n"
                      f"       {CLASS_USAGE}\n       {MERGE_USAGE}",
                description="Grade students' 4D grids against a world; or, with --controllers, run a class's\n"
                            "controllers over worlds and starts (its options below); --merge joins the CSVs\n"
                            "of --shard parts.",
                epilog="\n".join(["options with --controllers:", *_class_parser().format_help().split(
                    "options:\n", 1)[-1].splitlines()]),
                formatter_class=argparse.RawDescriptionHelpFormatter)
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
