"""Webots' Keyboard for controllers run by maze_mapper.run: the keys come from a script of
timed keys (the runner's --keys FILE), else from the terminal the runner was started in, else
there are none (getKey() returns -1).

Webots' rules (its Keyboard reference and its C library's keyboard.c):
  - enable(sampling_period) (ms), disable(), getSamplingPeriod(); the keys are sampled every
    sampling period from the enable on, the first after one whole period;
  - getKey() returns the keys pressed at the last sample, one a call (up to 7), then -1; the
    step after a step with no sample finds none (-1); called while disabled it prints Webots'
    error line and returns -1;
  - a key is its ASCII code (a letter's upper-case code) or a special code (Keyboard.UP, ...),
    with Keyboard.SHIFT, CONTROL, ALT or-ed in when such a modifier is held; code & KEY is the
    key without its modifiers.

A key script (--keys FILE) says which keys are held from which simulated time on:

    # comment (to the end of the line); blank lines are skipped
    0.0   UP              # UP held from 0 s ...
    2.5   LEFT SHIFT+A    # ... until 2.5 s, then LEFT and Shift+A held together
    3.0   -               # nothing held from 3 s on
    4     A

Each line is TIME KEY... : TIME in seconds of simulated time (Robot.getTime()), strictly
increasing from line to line; the keys named are held from TIME until the next line's TIME
(the last line's until the end), `-` for none, at most 7. A key is [MODIFIER+]...NAME with
MODIFIER one of SHIFT, CONTROL, ALT and NAME one of Webots' key names (END, HOME, LEFT, UP,
RIGHT, DOWN, PAGEUP, PAGEDOWN, NUMPAD_HOME, NUMPAD_LEFT, NUMPAD_UP, NUMPAD_RIGHT, NUMPAD_DOWN,
NUMPAD_END), SPACE, one printable character (a letter is its upper-case code, as Webots reports
it: `a` and `A` are both 65; `#` starts a comment, so the # key is written 35), or a key code of
two or more digits (65 is A). Names are read
without regard to case. An error is one line, `FILE:LINE:COL: error: ...`.

From a terminal (standard input a terminal, no --keys, the runner not a background job of
it), the terminal is put in a mode that hands each key at once without echoing it (Ctrl-C
still stops the run), and put back as it was when the controller ends, fails or is stopped by
a signal (before the summary), and while the runner is suspended (Ctrl-Z). A terminal
reports presses, not releases: a key read is pressed for the sample it is read in (held keys
repeat at the terminal's own rate). Read: printable characters (a lower-case letter as its
code, an upper-case one with SHIFT), Enter (4, Webots' code for Return), Ctrl+letter (CONTROL),
the arrows, Home, End, Page Up, Page Down, and the arrows with Shift, Alt or Control.
"""

import bisect
import math
import os
import re
import signal
import sys

END, HOME, LEFT, UP, RIGHT, DOWN = 312, 313, 314, 315, 316, 317
PAGEUP, PAGEDOWN = 366, 367
NUMPAD_HOME, NUMPAD_LEFT, NUMPAD_UP, NUMPAD_RIGHT, NUMPAD_DOWN = 375, 376, 377, 378, 379
NUMPAD_END = 382
KEY, SHIFT, CONTROL, ALT = 0x0000FFFF, 0x00010000, 0x00020000, 0x00040000
MAX_KEYS = 7  # keys getKey() reports in one sample (Webots' limit)
RETURN = 4  # Webots' code for the Return key

NAMES = {"END": END, "HOME": HOME, "LEFT": LEFT, "UP": UP, "RIGHT": RIGHT, "DOWN": DOWN,
         "PAGEUP": PAGEUP, "PAGEDOWN": PAGEDOWN, "NUMPAD_HOME": NUMPAD_HOME, "NUMPAD_LEFT": NUMPAD_LEFT,
         "NUMPAD_UP": NUMPAD_UP, "NUMPAD_RIGHT": NUMPAD_RIGHT, "NUMPAD_DOWN": NUMPAD_DOWN,
         "NUMPAD_END": NUMPAD_END, "SPACE": ord(" ")}
MODIFIERS = {"SHIFT": SHIFT, "CONTROL": CONTROL, "ALT": ALT}


class KeyScriptError(ValueError):
    """A key script that cannot be read; the message is `FILE:LINE:COL: error: ...`."""


def char_code(char):
    """Webots' code of a printable character: a letter's upper-case code."""
    return ord(char.upper()) if "a" <= char <= "z" else ord(char)


def parse_key(word):
    """The code of one key as a script names it; ValueError (the message, the column in the
    word, from 0) for a key no keyboard has."""
    if len(word) > 1 and word.endswith("++"):  # a modifier and the + key
        head, name = word[:-2], "+"
    elif len(word) > 1 and "+" in word:
        head, _, name = word.rpartition("+")
    else:
        head, name = "", word
    modifiers = 0
    at = 0
    for part in head.split("+") if head else []:
        if part.upper() not in MODIFIERS:
            raise ValueError(f"'{part}' is no modifier (SHIFT, CONTROL or ALT)", at)
        modifiers |= MODIFIERS[part.upper()]
        at += len(part) + 1
    if name.upper() in NAMES:
        return modifiers | NAMES[name.upper()]
    if len(name) == 1 and " " < name <= "~":
        return modifiers | char_code(name)
    if re.fullmatch(r"[0-9]{2,}", name):
        code = int(name)
        if code > KEY:
            raise ValueError(f"key code {code} is beyond {KEY} (modifiers are written SHIFT+, CONTROL+, ALT+)", at)
        return modifiers | code
    raise ValueError(f"unknown key '{name}' (a key name such as UP or PAGEDOWN, one printable character, "
                     "or a code of two or more digits)", at)


class KeyScript:
    """The keys a --keys file holds at each simulated time."""

    def __init__(self, times_s, keys):
        self.times_s = times_s  # increasing
        self.keys = keys  # keys[i]: the codes held from times_s[i] on

    def held_at(self, time_s):
        i = bisect.bisect_right(self.times_s, time_s + 1e-9) - 1
        return self.keys[i] if i >= 0 else ()


def _script_line(words, path, number, line):
    """(time_s, codes) of one script line's words [(column from 0, word)]."""
    def fail(column, message):
        raise KeyScriptError(f"{path}:{number}:{column + 1}: error: {message}")
    column, word = words[0]
    try:
        time_s = float(word)
    except ValueError:
        fail(column, f"expected a time in seconds, got '{word}'")
    if not (math.isfinite(time_s) and time_s >= 0.0):
        fail(column, f"the time must be a number of seconds, 0 or more (got {word})")
    if len(words) < 2:
        fail(len(line.rstrip()), "expected the keys held from this time on (or - for none)")
    if len(words) == 2 and words[1][1] == "-":
        return time_s, ()
    if len(words) - 1 > MAX_KEYS:
        fail(words[MAX_KEYS + 1][0], f"at most {MAX_KEYS} keys are held at once (Webots' limit)")
    codes = []
    for column, word in words[1:]:
        try:
            codes.append(parse_key(word))
        except ValueError as e:
            fail(column + e.args[1], e.args[0])
    return time_s, tuple(codes)


def read_key_script(path):
    """The KeyScript of a --keys file; KeyScriptError naming the file, line and column of the
    first thing wrong in it (or `error: cannot read FILE: ...`)."""
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except (OSError, UnicodeDecodeError) as e:
        raise KeyScriptError(f"error: cannot read --keys {path}: {getattr(e, 'strerror', None) or e}") from None
    times, keys = [], []
    for number, line in enumerate(text.splitlines(), start=1):
        content = line.split("#", 1)[0]
        words = [(m.start(), m.group()) for m in re.finditer(r"\S+", content)]
        if not words:
            continue
        time_s, codes = _script_line(words, path, number, content)
        if times and time_s <= times[-1]:
            raise KeyScriptError(f"{path}:{number}:{words[0][0] + 1}: error: the time {words[0][1]} s is not "
                                 f"after the line before's {times[-1]:g} s (times increase line by line)")
        times.append(time_s)
        keys.append(codes)
    if not times:
        raise KeyScriptError(f"{path}:1:1: error: the key script holds no line (TIME KEY..., e.g. '0.5 UP')")
    return KeyScript(times, keys)


_ESCAPES = {"A": UP, "B": DOWN, "C": RIGHT, "D": LEFT, "H": HOME, "F": END}
_TILDES = {"1": HOME, "4": END, "5": PAGEUP, "6": PAGEDOWN, "7": HOME, "8": END}
_XTERM_MODIFIERS = {2: SHIFT, 3: ALT, 4: SHIFT | ALT, 5: CONTROL, 6: SHIFT | CONTROL, 7: CONTROL | ALT,
                    8: SHIFT | CONTROL | ALT}


def _escape(data, at):
    """(code or None, next index) of the escape sequence at data[at] (an ESC)."""
    m = re.compile(rb"\x1b(?:\[|O)([0-9;]*)([A-Za-z~])").match(data, at)
    if m is None:
        return None, at + 1  # a lone Escape: not a key Webots reports here
    params = [int(p) for p in m.group(1).split(b";") if p]
    final = m.group(2).decode()
    modifier = _XTERM_MODIFIERS.get(params[1], 0) if len(params) > 1 else 0
    if final == "~":
        code = _TILDES.get(str(params[0]) if params else "")
    else:
        code = _ESCAPES.get(final)
    return (None if code is None else code | modifier), m.end()


def decode_terminal(data):
    """The Webots key codes of the bytes a terminal sent (see the module's description)."""
    codes = []
    at = 0
    while at < len(data):
        byte = data[at]
        if byte == 0x1B:
            code, at = _escape(data, at)
        else:
            at += 1
            if 0x20 <= byte <= 0x7E:
                char = chr(byte)
                code = char_code(char) | (SHIFT if "A" <= char <= "Z" else 0)
            elif byte in (0x0A, 0x0D):
                code = RETURN
            elif 1 <= byte <= 26:
                code = CONTROL | (ord("A") + byte - 1)
            else:
                code = None
        if code is not None:
            codes.append(code)
    return codes


class Terminal:
    """The runner's terminal, read a key at a time without echo; restore() puts it back."""

    def __init__(self, fd):
        import termios
        self._termios = termios
        self.fd = fd
        self.saved = termios.tcgetattr(fd)
        self._previous = {}
        self._raw()
        for signum, handler in ((signal.SIGTSTP, self._on_suspend), (signal.SIGCONT, self._on_continue)):
            try:
                self._previous[signum] = signal.signal(signum, handler)
            except ValueError:  # not the main thread: no suspend handling
                pass

    def _raw(self):
        mode = self._termios.tcgetattr(self.fd)
        mode[3] &= ~(self._termios.ICANON | self._termios.ECHO)  # lflags; ISIG stays: Ctrl-C stops the run
        mode[6][self._termios.VMIN] = 0
        mode[6][self._termios.VTIME] = 0
        self._termios.tcsetattr(self.fd, self._termios.TCSANOW, mode)

    def _on_suspend(self, signum, frame):
        self._termios.tcsetattr(self.fd, self._termios.TCSANOW, self.saved)
        signal.signal(signal.SIGTSTP, signal.SIG_DFL)
        os.kill(os.getpid(), signal.SIGTSTP)

    def _on_continue(self, signum, frame):
        signal.signal(signal.SIGTSTP, self._on_suspend)
        self._raw()

    def read(self):
        """The codes of the keys typed since the last read (never waits)."""
        import select
        data = b""
        while select.select([self.fd], [], [], 0)[0]:
            chunk = os.read(self.fd, 1024)
            if not chunk:
                break
            data += chunk
        return decode_terminal(data)

    def restore(self):
        self._termios.tcsetattr(self.fd, self._termios.TCSADRAIN, self.saved)
        for signum, handler in self._previous.items():
            signal.signal(signum, handler)
        self._previous = {}


class _State:
    """The robot's one keyboard (every Keyboard object is a view of it, as in Webots)."""

    def __init__(self):
        self.script = None  # the --keys script, or None
        self.terminal = None  # the Terminal read, or None
        self.period_ms = 0
        self.enabled_at_ms = 0.0
        self.samples = 0  # samples taken since the enable
        self.last_ms = 0.0  # the robot's time at the last step
        self.keys = []  # the keys of the last sample, in order
        self.pointer = 0

    def sample(self, now_ms):
        """After a step (the robot's time now_ms): the keys of a sample taken in the step, else none."""
        self.keys, self.pointer = [], 0
        if self.period_ms <= 0:
            return
        if now_ms < self.last_ms:  # a simulationReset: the time is back at 0, the sampling goes on from there
            self.enabled_at_ms, self.samples = 0.0, 0
        self.last_ms = now_ms
        due = int((now_ms - self.enabled_at_ms + 1e-6) // self.period_ms)
        if due <= self.samples:
            return
        self.samples = due
        if self.script is not None:
            self.keys = list(self.script.held_at(now_ms / 1000.0))
        elif self.terminal is not None:
            self.keys = self.terminal.read()[:MAX_KEYS]


state = _State()


def _now_ms():
    from . import controller
    robot = controller.Robot.created
    return 0.0 if robot is None else robot.getTime() * 1000.0


def use_script(script):
    """The runner's --keys: the keys come from this KeyScript."""
    state.__init__()
    state.script = script


def _in_background(fd):
    """Whether the runner is a background job of its controlling terminal fd (changing its mode
    would stop the runner). A terminal that is not the controlling one: never."""
    try:
        return os.tcgetpgrp(fd) != os.getpgrp()
    except OSError:
        return False


def use_terminal_if_any():
    """Without --keys: the runner's standard input, when it is a terminal, gives the keys."""
    state.__init__()
    try:
        fd = sys.stdin.fileno() if sys.stdin is not None else -1
        if fd >= 0 and os.isatty(fd) and not _in_background(fd):
            state.terminal = Terminal(fd)
    except (OSError, ValueError, ImportError):  # no terminal to read
        state.terminal = None


def release():
    """The run's end: the terminal as it was, the keyboard disabled."""
    if state.terminal is not None:
        try:
            state.terminal.restore()
        except Exception:  # the terminal is gone (hang-up): nothing to restore
            pass
    state.__init__()


class Keyboard:
    """Webots' Keyboard (the module's description)."""

    END, HOME, LEFT, UP, RIGHT, DOWN = END, HOME, LEFT, UP, RIGHT, DOWN
    PAGEUP, PAGEDOWN = PAGEUP, PAGEDOWN
    NUMPAD_HOME, NUMPAD_LEFT, NUMPAD_UP, NUMPAD_RIGHT, NUMPAD_DOWN, NUMPAD_END = (
        NUMPAD_HOME, NUMPAD_LEFT, NUMPAD_UP, NUMPAD_RIGHT, NUMPAD_DOWN, NUMPAD_END)
    KEY, SHIFT, CONTROL, ALT = KEY, SHIFT, CONTROL, ALT

    def __init__(self, sampling_period=None):
        """Keyboard() enables the keyboard at the basic time step, Keyboard(p) at p ms,
        Keyboard(0) leaves it as it is (Webots R2023b's constructor)."""
        if sampling_period != 0:
            from . import controller
            robot = controller.Robot.created
            basic = 32 if robot is None else int(robot.getBasicTimeStep())
            self.enable(basic if sampling_period is None else sampling_period)

    def enable(self, sampling_period):
        state.period_ms = int(sampling_period)
        state.enabled_at_ms = _now_ms()
        state.samples = 0
        state.keys, state.pointer = [], 0

    def disable(self):
        self.enable(0)

    def getSamplingPeriod(self):
        return state.period_ms

    @property
    def sampling_period(self):
        return state.period_ms

    @sampling_period.setter
    def sampling_period(self, period):
        self.enable(0 if period is None else period)

    def getKey(self):
        if state.period_ms <= 0:
            print("Error: wb_keyboard_get_key() called for a disabled device! Please use: wb_keyboard_enable().",
                  file=sys.stderr)
        if state.pointer >= len(state.keys):
            return -1
        state.pointer += 1
        return state.keys[state.pointer - 1]

    getKeyCode = getKey

    def get_key(self):
        """The key as Webots' Python API names it ('shift-up', 'control-A', ...; Alt is spelt
        'atl-' there, and so here); '' for none."""
        code = self.getKey()
        if code < 0:
            return ""
        words = "".join(w for bit, w in ((SHIFT, "shift-"), (CONTROL, "control-"), (ALT, "atl-")) if code & bit)
        base = code & KEY
        names = {v: k.lower().replace("_", " ").replace("page", "page ") for k, v in NAMES.items() if k != "SPACE"}
        return words + names.get(base, chr(base))
