"""How maze_mapper.run runs a controller's file: as Webots starts it (in its own folder, as
__main__, Webots' `controller` module resolved to maze_mapper's), and as carefully as the
program's commands run:

- SIGINT, SIGTERM and SIGHUP go through the commands' own handler (common/interrupt.hpp,
  installed by the runner): while the controller runs, a signal is recorded and the
  controller's next Robot.step() returns -1, so the controller ends as the simulation ends. A
  controller that does not step within GRACE_S of the signal (a loop without steps) gets
  KeyboardInterrupt. Python's own KeyboardInterrupt on Ctrl-C is replaced by this: Ctrl-C
  stops the run as SIGTERM does, and the summary names it.
- A child the controller forks (os.fork()) never ends the run: its steps return -1 at once
  and leave the trace alone, the parent's unfinished files are never its to remove, the stop
  signals end it as any process, and when its controller code ends it exits quietly, with the
  controller's status, before the runner's ending.
- The status of the controller's end fits an exit status: sys.exit(N) with N outside 0..255
  is a failed controller (1); any exception, BaseException subclasses and GeneratorExit
  included, is a failed controller with its traceback.
"""

import _thread
import os
import runpy
import signal
import sys
import threading
import traceback

from maze_mapper import _native
from maze_mapper.controller import SimulationEnded

# Seconds a controller has, once a stop signal is recorded, to reach its next step.
GRACE_S = 2.0

_runner_pid = None  # the runner's process while it runs a controller, else None


def _flush_stdio():
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):
            pass


def _before_fork():
    """What the controller printed goes out once, from the parent, not again from a child."""
    if _runner_pid is not None:
        _flush_stdio()


def _in_forked_child():
    if _runner_pid is None:
        return
    _native.forget_temporaries()
    try:
        signal.signal(signal.SIGINT, signal.default_int_handler)
        signal.signal(signal.SIGTERM, signal.SIG_DFL)
        signal.signal(signal.SIGHUP, signal.SIG_DFL)
    except ValueError:  # forked from a thread other than the main one
        pass


os.register_at_fork(before=_before_fork, after_in_child=_in_forked_child)


class _SignalWatch:
    """While the controller runs: once a stop signal is recorded, KeyboardInterrupt in the
    controller if it has not ended GRACE_S later (its steps return -1 from the signal on)."""

    def __init__(self):
        self._done = threading.Event()
        self._lock = threading.Lock()
        self._finished = False
        self._thread = threading.Thread(target=self._watch, name="maze_mapper signal watch", daemon=True)

    def _watch(self):
        while not self._done.wait(0.05):
            if _native.interrupted():
                if not self._done.wait(GRACE_S):
                    with self._lock:
                        if not self._finished:
                            _thread.interrupt_main()
                return

    def __enter__(self):
        self._thread.start()
        return self

    def __exit__(self, *exc):
        with self._lock:
            self._finished = True
        self._done.set()
        self._thread.join()


def _exit_code(code):
    """(how the controller ended, exit status) for sys.exit(code)."""
    if code is None:
        return "controller finished", 0
    if not isinstance(code, int):
        print(code, file=sys.stderr)
        return "controller failed", 1
    status = code if 0 <= code <= 255 else 1  # a code no exit status holds: failed
    return ("controller finished" if status == 0 else "controller failed"), status


def _run_file(path, controller_args):
    """Runs the controller's file as __main__ in its own folder, the course's fairis_lib before
    our stand-in; returns (how it ended, exit status)."""
    here = os.path.dirname(os.path.abspath(__file__))
    path = os.path.abspath(path)
    folder = os.path.dirname(path)
    saved_argv, saved_path, saved_cwd = sys.argv, list(sys.path), os.getcwd()
    saved_modules = set(sys.modules)
    sys.argv = [path] + list(controller_args)
    sys.path[:0] = [os.path.join(here, "_webots"), folder]
    sys.path.append(os.path.join(here, "_fairis"))
    sys.modules.pop("controller", None)
    os.chdir(folder)
    try:
        runpy.run_path(path, run_name="__main__")
        return "controller finished", 0
    except SimulationEnded:
        return "simulation ended", 0
    except SystemExit as e:
        return _exit_code(e.code)
    except KeyboardInterrupt:
        if _native.interrupted():  # the signal watch's: the run's ending names the signal
            return "stopped", 0
        traceback.print_exc()
        return "controller failed", 1
    except BaseException:  # the controller's own error: its traceback, as Webots' console shows it
        traceback.print_exc()
        return "controller failed", 1
    finally:
        os.chdir(saved_cwd)
        sys.argv, sys.path[:] = saved_argv, saved_path
        for name in set(sys.modules) - saved_modules:  # the controller's own modules
            if name.split(".")[0] in ("fairis_lib", "fairis_tools", "controller"):
                del sys.modules[name]


def run(path, controller_args):
    """Runs the controller (see the module's words); returns (how it ended, exit status) in the
    runner's process. A stop signal recorded meanwhile: maze_mapper._native.interrupted()."""
    global _runner_pid
    _runner_pid = os.getpid()
    ended = ("controller failed", 1)
    try:
        with _native.SignalsStopWork(), _SignalWatch():
            ended = _run_file(path, controller_args)
    except KeyboardInterrupt:  # the signal watch's, come as the controller ended
        pass
    if os.getpid() != _runner_pid:  # a child the controller forked: never the run's ending
        _flush_stdio()
        os._exit(ended[1])
    _runner_pid = None
    return ended
