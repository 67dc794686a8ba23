"""python3 -m maze_mapper.run CONTROLLER.py --world WORLD [options] [-- CONTROLLER ARGS...]

Runs a Webots Python controller against maze_mapper's embedded simulator, as Webots would
start it: `from controller import Robot` imports maze_mapper's controller module, sys.argv is
the controller's path and its arguments (Webots' controllerArgs), and Robot.step() returns -1
once the simulation ends (--max-steps). The controller sees only its devices, never the maze.
When it ends, the runner prints a summary; if the controller handed its grid to
maze_mapper.keep_grid(), the summary scores it against the world's truth as `maze_mapper run`
scores its own map. Exit status: the controller's (1 for an uncaught exception), 2 for bad
input to the runner.
"""

import argparse
import os
import runpy
import sys
import time
import traceback

import maze_mapper
from maze_mapper import _native
from maze_mapper.controller import Robot, SimulationEnded

EXIT_USAGE = 2


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        print(f"error: {message}", file=sys.stderr)
        sys.exit(EXIT_USAGE)


def _parse(argv):
    p = _Parser(prog="python3 -m maze_mapper.run",
                description="Run a Webots Python controller against the embedded simulator.")
    p.add_argument("controller", help="the controller's .py file (it does `from controller import Robot`)")
    p.add_argument("--world", required=True, help="a maze file: text map, mms num or wall-segment XML")
    p.add_argument("--robot", default="hambot", help="a built-in robot profile or a FILE.json (default hambot)")
    p.add_argument("--seed", type=int, default=42, help="the sensors' noise seed (default 42)")
    p.add_argument("--noise", type=float, help="lidar noise as a fraction of max range (0: exact sensors)")
    p.add_argument("--cell-size", type=float, help="cell size in m of a text or num world (default 1)")
    p.add_argument("--max-steps", type=int, default=100_000,
                   help="basic time steps before Robot.step() returns -1 (default 100000)")
    args, rest = p.parse_known_args(argv)
    if rest and rest[0] == "--":
        rest = rest[1:]
    elif rest:
        p.error(f"unrecognized arguments: {' '.join(rest)} (controller arguments follow --)")
    if args.max_steps < 1:
        p.error(f"--max-steps must be at least 1 (got {args.max_steps})")
    if args.seed < 0:
        p.error(f"--seed must be 0 or more (got {args.seed})")
    if not os.path.isfile(args.controller):
        p.error(f"cannot read {args.controller}: no such file")
    return args, rest


def _run_controller(path, controller_args):
    """Runs the controller's file as __main__ with Webots' `controller` module resolved to
    ours; returns (how it ended, exit status)."""
    here = os.path.dirname(os.path.abspath(__file__))
    saved_argv, saved_path = sys.argv, list(sys.path)
    sys.argv = [path] + list(controller_args)
    sys.path[:0] = [os.path.join(here, "_webots"), os.path.dirname(os.path.abspath(path))]
    sys.modules.pop("controller", None)
    try:
        runpy.run_path(path, run_name="__main__")
        return "controller finished", 0
    except SimulationEnded:
        return "simulation ended", 0
    except SystemExit as e:
        code = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
        if e.code is not None and not isinstance(e.code, int):
            print(e.code, file=sys.stderr)
        return ("controller finished" if code == 0 else "controller failed"), code
    except KeyboardInterrupt:
        return "interrupted", 130
    except Exception:  # the controller's own error: its traceback, as Webots' console shows it
        traceback.print_exc()
        return "controller failed", 1
    finally:
        sys.argv, sys.path[:] = saved_argv, saved_path


def _percent(value):
    return f"{value:.2f}%"


def _summary(args, world, simulation, end, wall_time_ms):
    lines = [
        f"controller: {args.controller}",
        f"world: {args.world}",
        f"size: {world.width}x{world.height}",
        f"robot: {simulation.robot_name}",
        f"seed: {args.seed}",
        f"end: {end}",
        f"steps: {simulation.steps}",
        f"sim_time_s: {simulation.time_s:.3f}",
    ]
    if maze_mapper._kept is not None:
        grid, visited, initial = maze_mapper._kept
        result = maze_mapper.score(world, grid, visited, initial_log_odds=initial)
        shape = grid.array.shape if isinstance(grid, maze_mapper.OccupancyGrid) else getattr(grid, "shape", ())
        lines += [
            f"subcells: {shape[-1] if shape else '?'}",
            f"visited: {result.visited_reachable_cells}",
            f"reachable: {result.reachable_cells}",
            f"coverage: {_percent(result.coverage_percent)}",
            f"wall_accuracy: {_percent(result.wall_accuracy_percent)}",
        ]
        if result.wrong_where_looked:
            named = ", ".join(repr(s) for s in result.first_wrong_where_looked)
            more = ", ..." if result.wrong_where_looked > len(result.first_wrong_where_looked) else ""
            n = result.wrong_where_looked
            lines.append(f"wrong_sides: {n} side{'' if n == 1 else 's'} of visited cells learned wrong: {named}{more}")
    else:
        lines.append("grid: none kept (maze_mapper.keep_grid scores a controller's grid)")
    lines.append(f"wall_time_ms: {wall_time_ms:.0f}")
    return "\n".join(lines)


def main(argv=None):
    args, controller_args = _parse(sys.argv[1:] if argv is None else argv)
    try:
        world = maze_mapper.load_world(args.world, cell_size_m=args.cell_size)
        for warning in world.warnings:
            print(warning, file=sys.stderr)
        simulation = _native.Simulation(world, robot=args.robot, seed=args.seed, noise=args.noise,
                                        max_steps=args.max_steps)
    except maze_mapper.Error as e:
        print(e, file=sys.stderr)
        return EXIT_USAGE
    maze_mapper._kept = None
    simulation.make_current()
    started = time.perf_counter()
    try:
        end, status = _run_controller(args.controller, controller_args)
    finally:
        simulation.release_current()
        Robot.created = None
    wall_time_ms = (time.perf_counter() - started) * 1000.0
    sys.stdout.flush()
    try:
        print("\n" + _summary(args, world, simulation, end, wall_time_ms))
    except maze_mapper.Error as e:
        print(e, file=sys.stderr)
        return status or EXIT_USAGE
    return status


if __name__ == "__main__":
    sys.exit(main())
