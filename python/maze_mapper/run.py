"""python3 -m maze_mapper.run CONTROLLER.py [--world WORLD] [options] [-- CONTROLLER ARGS...]

Runs a Webots Python controller against maze_mapper's embedded simulator, as Webots would
start it: in the controller's own folder (so the course's '../../worlds/...' paths resolve),
`from controller import Robot` (or Supervisor) imports maze_mapper's controller module,
sys.argv is the controller's path and its arguments (Webots' controllerArgs), and
Robot.step() returns -1 once the simulation ends (--time-limit, --max-steps, --wall-limit).
The runner's own paths (CONTROLLER, --world, --robot, --out) are taken from the folder it is
started in, where the user typed them; a controller takes a path argument from there with
maze_mapper.user_path(). Without --world the world is the course's empty floor, which a
supervisor controller fills (the course's load_environment); with it, a maze or an arena
file. The course's own fairis_lib is used when it is importable; maze_mapper's stand-in
serves where it is not.
When the controller ends, the runner prints a summary; if the controller handed its grid to
maze_mapper.keep_grid(), the summary scores it against a maze's truth as `maze_mapper run`
scores its own map; on an arena, a metric map handed to maze_mapper.keep_map() is drawn. With
--out DIR it writes the run's files there (docs/course.md), each whole or absent, with what the
controller printed (controller.log, and controller_lines.csv: the step and true pose of each
line).
SIGINT (Ctrl-C), SIGTERM and SIGHUP stop the run as they stop `maze_mapper run`: the
controller's next step returns -1 (KeyboardInterrupt in a controller that has not stepped 2 s
later), the summary's end is `stopped (interrupted by SIGTERM)`, the files are written, and
the exit status is 128 + the signal; a signal once the summary is being written ends the
process at once, its unfinished files removed. A child the controller forks never ends the
run nor touches its files. Exit status: the controller's (sys.exit's code; 1 for an uncaught
exception or a code outside 0..255), 2 for bad input to the runner, 4 when the disk is full
(said on one `error:` line after the summary; the run is not blamed on the controller),
128 + a stop signal.
"""

import argparse
import errno
import json
import math
import os
import random
import re
import sys
import textwrap
import time

import maze_mapper
from maze_mapper import _controller_log, _controller_run, _native, controller, devices, keyboard, scene
from maze_mapper.controller import Robot

_KEY = _native.report_key  # the summary keys, spelled once for every report

EXIT_USAGE = 2
_BASIC_STEP_MS = 32  # the simulator's basic time step


class _HelpFormatter(argparse.HelpFormatter):
    """Help lines wrapped at spaces only, so that a name such as ir-ring stays whole."""

    def _split_lines(self, text, width):
        return textwrap.wrap(" ".join(text.split()), width, break_on_hyphens=False)


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        print(f"error: {message}", file=sys.stderr)
        sys.exit(EXIT_USAGE)


def _parse(argv):
    p = _Parser(prog="python3 -m maze_mapper.run", formatter_class=_HelpFormatter,
                description="Run a Webots Python controller against the embedded simulator.")
    p.add_argument("controller", help="the controller's .py file (it does `from controller import Robot`)")
    p.add_argument("--world", help="a maze or arena file (text map, mms num, XML, room); default: the course's "
                                     "empty floor, which the controller's supervisor fills")
    # The options a run of every kind takes read as `maze_mapper run --help` words them: their
    # help lines come from the program's one table (maze_mapper._native.option_help), a leading
    # "N: " the value's name, as the program's help shows it.
    def shared(flag):
        text = _native.option_help(flag)
        named = re.match(r"([A-Z][A-Za-z0-9 .]*): (.*)", text, re.S)
        metavar, words = (named.group(1), named.group(2)) if named else (None, text)
        return {"metavar": metavar, "help": words.replace("%", "%%")}  # argparse formats help with %
    p.add_argument("--robot", default="hambot", **shared("--robot"))
    p.add_argument("--seed", type=int, default=42, **shared("--seed"))
    p.add_argument("--noise", type=float, **shared("--noise"))
    p.add_argument("--cell-size", type=float, **shared("--cell-size"))
    p.add_argument("--start", help="the world's start: pos:N (its N-th start position) or random (one of them, "
                                   "drawn with --seed), as `maze_mapper run --start`; on an arena too")
    p.add_argument("--max-steps", type=int, default=100_000, **shared("--max-steps"))
    p.add_argument("--time-limit", type=float, **shared("--time-limit"))
    p.add_argument("--wall-limit", type=float,
                   help="wall-clock seconds after which Robot.step() returns -1 (a guard for a class's runs)")
    p.add_argument("-o", "--out", **shared("--out"))
    p.add_argument("--keys", metavar="FILE",
                   help="the keyboard's keys from a script of timed keys (lines 'TIME KEY...', docs/python.md); "
                        "without it a terminal's keys, else none")
    p.add_argument("--device", metavar="TYPE[:NAME]", action="append", default=[],
                   help="adds a compass, accelerometer, gyro or led to the robot (repeatable; NAME defaults to "
                        "TYPE)")
    # Everything after the first `--` is the controller's, whether runner options come before it
    # or not (argparse would drop a `--` that directly follows the controller's path).
    split = argv.index("--") if "--" in argv else len(argv)
    args, unknown = p.parse_known_args(argv[:split])
    if unknown:
        p.error(f"unrecognized arguments: {' '.join(unknown)} (controller arguments follow --)")
    rest = argv[split + 1:]
    if args.max_steps < 1:
        p.error(f"--max-steps must be at least 1 (got {args.max_steps})")
    args.time_limited = False  # whether --time-limit, not --max-steps, bounds the run
    if args.time_limit is not None:
        if not (args.time_limit > 0 and math.isfinite(args.time_limit)):
            p.error(f"--time-limit must be a number of seconds above 0 (got {args.time_limit})")
        timed_steps = max(1, math.ceil(args.time_limit * 1000 / _BASIC_STEP_MS - 1e-9))  # the first step at or past it
        args.time_limited = timed_steps <= args.max_steps
        args.max_steps = min(args.max_steps, timed_steps)
    if args.wall_limit is not None and not (args.wall_limit > 0 and math.isfinite(args.wall_limit)):
        p.error(f"--wall-limit must be a number of seconds above 0 (got {args.wall_limit})")
    if args.start is not None:
        if args.world is None:
            p.error("--start needs --world (on the course's empty floor the controller chooses its start)")
        if args.start != "random" and not re.fullmatch(r"pos:[1-9][0-9]*", args.start):
            p.error(f"--start must be pos:N (N from 1) or random (got {args.start})")
    if args.seed < 0:
        p.error(f"--seed must be 0 or more (got {args.seed})")
    if not os.path.isfile(args.controller):
        p.error(f"cannot read {args.controller}: no such file")
    try:
        args.device = [devices.parse_device_option(text) for text in args.device]
    except ValueError as e:
        p.error(str(e))
    return args, rest


def _check_devices(args, simulation):
    """The --device names against the robot's own devices and each other; maze_mapper.Error."""
    taken = set(simulation.device_names())
    if simulation.robot_name.startswith("hambot"):
        taken |= {"camera", "User Display", "Place Cell Display"}
    for kind, name in args.device:
        if name in taken:
            raise maze_mapper.Error(f"error: --device {kind}:{name}: the robot has a device named {name} already")
        taken.add(name)



class _Entries:
    """The runner's report as the program's Report takes it: (key, printed value or None, the
    value as JSON text); the C++ side prints the block and writes summary.json from it."""

    def __init__(self):
        self.items = []

    def both(self, key, text, value=None):
        self.items.append((key, text, json.dumps(text if value is None else value)))

    def json_only(self, key, value):
        self.items.append((key, None, json.dumps(value)))


def _two_decimals(percent):
    return round(percent * 100.0) / 100.0


def _world_entries(e, args, world, the_scene):
    if world is None:
        e.both("world", "the course's empty floor (17 x 17 m)")
        e.both("imported_nodes", str(the_scene.root.getField("children").getCount() - 1),  # all but the robot
               the_scene.root.getField("children").getCount() - 1)
        # Where the controller's walls stand (x_min, x_max, y_min, y_max): where a grader lays
        # the course's cells.
        if the_scene.walls_extent_m is not None:
            e.json_only("walls_extent_m", [round(v, 3) for v in the_scene.walls_extent_m])
    elif world.is_maze:
        e.both("world", args.world)
        e.both("size", f"{world.width}x{world.height}")
        e.json_only("width", world.width)
        e.json_only("height", world.height)
    else:
        e.both("world", args.world)
        e.both("arena", world.name)
        e.both("obstacles", str(world.obstacles), world.obstacles)


def _distance_m(the_scene):
    """The path the robot's body moved along, m (teleports left out)."""
    robot = Robot.created
    if robot is None or not hasattr(robot, "distance_m"):
        return 0.0
    robot._record_path(the_scene)  # the last step's move
    return robot.distance_m


def _map_entries(e, world):
    """What became of the metric map the controller kept (maze_mapper.keep_map): map.png and the
    replay's map draw it, unless a maze's 4D grid is kept (keep_grid), which they draw instead;
    a line says which map, or why there is no map.png."""
    kept = maze_mapper._kept_map
    grid_drawn = world is not None and world.is_maze and maze_mapper._kept is not None
    if kept is not None:
        e.both("map", "kept, not drawn (map.png and the replay draw the kept grid)" if grid_drawn else f"kept, {kept}",
               "kept")
    elif world is None or not world.is_maze:  # an arena, or the course's floor as the controller built it
        e.both("map", "none kept (maze_mapper.keep_map hands the runner a metric map: map.png, the replay's map)",
               "none")


def _grid_entries(e, world):
    """coverage and wall accuracy of the grid the controller kept (maze_mapper.keep_grid)."""
    if maze_mapper._kept is not None and (world is None or not world.is_maze):
        e.both("grid", "kept, not scored (the world is no maze)", "kept")
        return
    if maze_mapper._kept is None:
        if world is not None and world.is_maze:
            e.both("grid", "none kept (maze_mapper.keep_grid scores a controller's grid)", "none")
        return
    grid, visited, initial = maze_mapper._kept
    result = maze_mapper.score(world, grid, visited, initial_log_odds=initial)
    shape = grid.array.shape if isinstance(grid, maze_mapper.OccupancyGrid) else getattr(grid, "shape", ())
    e.both("subcells", str(shape[-1]) if shape else "?", shape[-1] if shape else None)
    e.both("visited", str(result.visited_reachable_cells), result.visited_reachable_cells)
    e.both(_KEY.reachable, str(result.reachable_cells), result.reachable_cells)
    e.both(_KEY.coverage, f"{result.coverage_percent:.2f}%", _two_decimals(result.coverage_percent))
    e.both(_KEY.wall_accuracy, f"{result.wall_accuracy_percent:.2f}%", _two_decimals(result.wall_accuracy_percent))
    if result.wrong_where_looked:
        named = ", ".join(repr(s) for s in result.first_wrong_where_looked)
        more = ", ..." if result.wrong_where_looked > len(result.first_wrong_where_looked) else ""
        n = result.wrong_where_looked
        e.both("wrong_sides", f"{n} side{'' if n == 1 else 's'} of visited cells learned wrong: {named}{more}", n)


def _landmark_entries(e, the_scene):
    """summary.json's landmarks (the world's and those the controller's supervisor built), each
    with its gap at the end: metres between the robot body's edge and the cylinder's surface
    (0 when they touch), what a lab that asks the robot to stop near a landmark grades."""
    if not the_scene.landmarks:
        return
    x, y, _, _ = the_scene.simulation.pose
    body = the_scene.simulation.body_radius_m
    e.json_only("landmarks", [
        {"x_m": round(m.x, 3), "y_m": round(m.y, 3), "radius_m": round(m.radius, 3),
         "color": [round(float(c), 3) for c in m.colors[:3]],  # its first recognition colour
         "gap_m": round(max(0.0, math.hypot(m.x - x, m.y - y) - m.radius - body), 3)}
        for m in the_scene.landmarks])


def _ending(args, simulation, controller_end, status):
    """The run's end and its message, as every run says them: the step limit when the simulation
    ended there (the controller then left its loop, or stepped on and was ended), else how the
    controller ended; a stop signal first (SIGINT, SIGTERM, SIGHUP), named as the commands name it."""
    if _native.interrupted():
        return "stopped", f"interrupted by {_native.interrupt_name()}"
    if controller.wall_limit_reached:
        return "wall-clock limit", ""
    if status == 0 and simulation.steps >= args.max_steps:
        if args.time_limited:
            return "time limit", f"{args.time_limit:g} s of simulated time"
        return "max steps", ""
    return controller_end, ""


def _report(args, world, the_scene, end, wall_time_ms):
    """The run's report entries, in the order every run reports its core keys."""
    simulation = the_scene.simulation
    e = _Entries()
    e.both("controller", args.controller)
    _world_entries(e, args, world, the_scene)
    e.json_only("model", None)  # the controller's own
    e.json_only("strategy", None)
    e.both("robot", simulation.robot_name)
    e.both("seed", str(args.seed), args.seed)
    end, message = end
    e.both("end", f"{end} ({message})" if message else end, end)
    e.json_only("end_message", message)
    e.both("steps", str(simulation.steps), simulation.steps)
    e.both("sim_time_s", f"{simulation.time_s:.3f}", simulation.time_s)
    x, y, _, yaw = simulation.pose
    e.both("final_pose", f"{x:.3f} {y:.3f} {math.degrees(yaw):.1f}",
           {"x_m": round(x, 3), "y_m": round(y, 3), "yaw_deg": round(math.degrees(yaw), 1)})
    distance = _distance_m(the_scene)
    e.both("distance_m", f"{distance:.3f}", round(distance, 3))
    e.both("collisions", str(simulation.collisions), simulation.collisions)
    the_scene.goal.look_for_controller_goals(Robot.created, simulation)
    if the_scene.goal.exists():
        e.both("goal", "reached" if simulation.goal_reached else "not reached")
    else:
        e.json_only("goal", None)
    _landmark_entries(e, the_scene)
    _grid_entries(e, world)
    _map_entries(e, world)
    e.both("wall_time_ms", f"{wall_time_ms:.0f}", wall_time_ms)
    return e.items


def _arena_start(args, world):
    """The arena's start pose --start chooses (x, y, yaw), or None for its first: pos:N its
    N-th start position, random one drawn with --seed."""
    starts = world.starts
    if args.start is None or not starts:
        return None
    if args.start == "random":
        return starts[random.Random(args.seed).randrange(len(starts))]
    n = int(args.start[4:])
    if n > len(starts):
        raise maze_mapper.Error(f"error: --start {args.start}: {args.world} has {len(starts)} start "
                                f"position{'' if len(starts) == 1 else 's'}")
    return starts[n - 1]


def _simulation(args):
    """(the world read, or None for the empty floor; the simulation). --start chooses a maze's
    or an arena's start position."""
    options = dict(robot=args.robot, seed=args.seed, noise=args.noise, max_steps=args.max_steps)
    if args.world is None:
        return None, _native.Simulation.empty_floor(**options)
    world = _native.load_world(args.world, cell_size_m=args.cell_size)
    if world.is_maze and args.start is not None:
        start_position = int(args.start[4:]) if args.start.startswith("pos:") else None
        world = _native.load_world(args.world, cell_size_m=args.cell_size, start_position=start_position,
                                       random_start=args.start == "random", seed=args.seed)
    for warning in world.warnings:
        print(warning, file=sys.stderr)
    simulation = _native.Simulation(world, **options)
    if not world.is_maze:
        start = _arena_start(args, world)
        if start is not None:
            simulation.teleport(start[0], start[1], 0.0, start[2])
    return world, simulation


def _goal(world):
    """The run's goal (scene.Goal): the maze's goal cells, the arena's goal points, or on the
    empty floor the ones the controller's library reads with its world."""
    if world is None:
        return scene.Goal(from_controller=True)
    if world.is_maze:
        return scene.Goal(cells=world.goals, cell_size_m=world.cell_size_m, origin=world.origin)
    return scene.Goal(points=world.goal_points)


def _run_files(args):
    """--out DIR prepared and checked against the run's inputs (as `maze_mapper run --out`), or
    None without --out; raises maze_mapper.Error when DIR cannot take the files."""
    if args.out is None:
        return None
    inputs = [("the controller", args.controller)]
    if args.world is not None:
        inputs.append(("the world", args.world))
    if os.path.isfile(args.robot):
        inputs.append(("--robot", args.robot))
    return _native.RunFiles(os.path.abspath(args.out), inputs)


def _print_summary(text):
    """Writes the summary on standard output, after what the controller printed; the errno of a
    write that failed (a full device), else None."""
    try:
        sys.stdout.flush()
        sys.stdout.write(text)
        sys.stdout.flush()
        return None
    except OSError as e:
        return e.errno


def _stdout_failed(error_number):
    """Standard output could not take the summary: said once, as the commands say it (exit
    status 4 for a full device, else 1); what is left unwritten goes nowhere."""
    null = os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, sys.stdout.fileno())
    os.close(null)
    if error_number in (errno.ENOSPC, errno.EDQUOT):
        print(f"error: cannot write standard output: {os.strerror(error_number)}", file=sys.stderr)
        return _native.NO_SPACE_EXIT_STATUS
    print("error: could not write to standard output", file=sys.stderr)
    return 1


def _secure_standard_streams():
    """A standard stream the caller closed (`>&-`) is /dev/null, for Python as for the C++ side,
    so that no file the run opens (its trace) takes its number."""
    _native.secure_standard_streams()
    for name, mode in (("stdin", "r"), ("stdout", "w"), ("stderr", "w")):
        if getattr(sys, name) is None:  # Python found the descriptor closed at its start
            setattr(sys, name, open(os.devnull, mode))


def main(argv=None):
    _secure_standard_streams()
    _native.install_signal_handlers()
    args, controller_args = _parse(sys.argv[1:] if argv is None else argv)
    maze_mapper._started_in = os.getcwd()  # where the user's paths are taken from (user_path)
    try:
        world, simulation = _simulation(args)
        _check_devices(args, simulation)
        script = None if args.keys is None else keyboard.read_key_script(args.keys)
        files = _run_files(args)
    except (maze_mapper.Error, keyboard.KeyScriptError) as e:
        print(e, file=sys.stderr)
        return EXIT_USAGE
    maze_mapper._kept = None
    maze_mapper._kept_map = None
    maze_mapper._map_recorder = files
    simulation.make_current()
    if files is not None:
        simulation.record_trace(files)
    scene.current = scene.Scene(simulation, world_file=args.world, goal=_goal(world))
    scene.current.world_read = world  # Supervisor.exportImage's floor
    devices.requested[:] = args.device
    devices.motion.poses = []
    if world is not None:
        scene.current.add_world_landmarks(world.landmarks)
    random.seed(args.seed)
    started = time.perf_counter()
    controller.wall_deadline = None if args.wall_limit is None else started + args.wall_limit
    controller.wall_limit_reached = False
    status = EXIT_USAGE
    try:
        if script is not None:
            keyboard.use_script(script)
        else:
            keyboard.use_terminal_if_any()
        log = _controller_log.ControllerLog(simulation)
        try:
            if files is None:
                end, status = _controller_run.run(args.controller, controller_args)
            else:
                with log.kept():
                    end, status = _controller_run.run(args.controller, controller_args)
        finally:
            keyboard.release()  # the terminal as it was, before the summary
        if _native.interrupted():
            status = _native.interrupted_exit_status()
        wall_time_ms = (time.perf_counter() - started) * 1000.0
        end = _ending(args, simulation, end, status)
        entries = _report(args, world, scene.current, end, wall_time_ms)
        stdout_failed = _print_summary("\n" + _native.format_entries(entries))
        if files is not None:
            kept = maze_mapper._kept
            # On the course's empty floor, the world the controller's supervisor built.
            drawn = world if world is not None else simulation.built_world()
            files.keep_text("controller.log", log.text())
            files.keep_text("controller_lines.csv", log.lines_csv())
            files.finish(entries, drawn, None if kept is None else kept[0], None if kept is None else kept[2])
        if stdout_failed is not None:
            return _stdout_failed(stdout_failed)
    except maze_mapper.NoSpaceError as e:  # after the summary, as the commands say it
        print(e, file=sys.stderr)
        return _native.NO_SPACE_EXIT_STATUS
    except maze_mapper.Error as e:
        print(e, file=sys.stderr)
        return status or EXIT_USAGE
    except RuntimeError as e:  # a write that failed otherwise: "error: cannot write ..."
        print(e, file=sys.stderr)
        return status or 1
    finally:
        maze_mapper._started_in = None
        simulation.release_current()
        Robot.created = None
        maze_mapper._map_recorder = None
        controller.wall_deadline = None
        keyboard.release()
        devices.requested[:] = []
        scene.current = None
    return status


if __name__ == "__main__":
    sys.exit(main())
