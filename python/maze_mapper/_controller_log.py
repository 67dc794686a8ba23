"""What a controller prints, kept for its run's --out folder as Webots' console shows it:
controller.log (standard output and error, in the order printed) and controller_lines.csv,
a row a line of the log: the step it was printed at, the simulated time and the robot's true
pose then, so that a line (a position estimate) can be compared with where the robot was.

The controller's sys.stdout and sys.stderr are wrapped while it runs; each write goes on to
the stream as before. What a child process or C code writes to the descriptors directly is
not seen.
"""

import math
import sys

LINE_COLUMNS = ["line", "step", "sim_time_s", "x_m", "y_m", "yaw_deg"]
# What the log keeps at most: a controller printing in a tight loop for hours still ends with
# its run's files, the log cut at this size with a last line that says so.
MAX_KEPT_BYTES = 64 << 20


class ControllerLog:
    """The log of one run: `with log.kept():` wraps sys.stdout and sys.stderr; text() and
    lines_csv() are the two files' contents."""

    def __init__(self, simulation):
        self._simulation = simulation
        self._parts = []
        self._rows = []  # a row a line: (line number from 1, step, time, x, y, yaw)
        self._line_open = False  # the last write left a line unfinished
        self._kept_bytes = 0
        self._dropped_bytes = 0  # written after the log reached MAX_KEPT_BYTES

    def _mark_line(self):
        s = self._simulation
        x, y, _, yaw = s.pose
        self._rows.append((len(self._rows) + 1, s.steps, s.time_s, x, y, yaw))

    def write(self, text):
        """Takes what a stream wrote: every line begun marks the step and pose of its start.
        Past MAX_KEPT_BYTES it only counts what it drops."""
        if self._dropped_bytes or self._kept_bytes + len(text) > MAX_KEPT_BYTES:
            self._dropped_bytes += len(text)
            return
        self._kept_bytes += len(text)
        for piece in text.splitlines(keepends=True):
            if not self._line_open:
                self._mark_line()
            self._line_open = not piece.endswith(("\n", "\r"))
        self._parts.append(text)

    def text(self):
        text = "".join(self._parts)
        if self._dropped_bytes:
            text += ("" if not text or text.endswith("\n") else "\n") + (
                f"[maze_mapper: the log ends here; {self._dropped_bytes} more characters the controller printed "
                f"are not kept (at most {MAX_KEPT_BYTES} a run)]\n")
        return text

    def lines_csv(self):
        rows = [",".join(LINE_COLUMNS)]
        rows += [f"{n},{step},{t:.3f},{x:.4f},{y:.4f},{math.degrees(yaw):.2f}" for n, step, t, x, y, yaw in self._rows]
        return "\n".join(rows) + "\n"

    def kept(self):
        return _Wrapped(self)


class _Tee:
    """A text stream that writes to `stream` and to the log."""

    def __init__(self, stream, log):
        self._stream, self._log = stream, log

    def write(self, text):
        written = self._stream.write(text)
        self._log.write(text)
        return written

    def writelines(self, lines):
        for line in lines:
            self.write(line)

    def __getattr__(self, name):  # flush, fileno, isatty, encoding, buffer ... as the stream's
        return getattr(self._stream, name)


class _Wrapped:
    def __init__(self, log):
        self._log = log
        self._saved = None

    def __enter__(self):
        self._saved = (sys.stdout, sys.stderr)
        sys.stdout, sys.stderr = _Tee(sys.stdout, self._log), _Tee(sys.stderr, self._log)
        return self._log

    def __exit__(self, *exc):
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError):
                pass
        sys.stdout, sys.stderr = self._saved
