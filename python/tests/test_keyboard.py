"""Webots' Keyboard under maze_mapper.run: its codes, its sampling, a script of timed keys
(--keys FILE) and the terminal."""

import os
import subprocess
import sys
import termios
import time

from conftest import REPO, run_controller, summary_of

from maze_mapper import keyboard
from maze_mapper.keyboard import Keyboard, decode_terminal

TELEOP = """
from controller import Robot, Keyboard
robot = Robot()
keyboard = robot.getKeyboard()
step = int(robot.getBasicTimeStep())
keyboard.enable(step)
left, right = robot.getDevice("left motor"), robot.getDevice("right motor")
for motor in (left, right):
    motor.setPosition(float("inf"))
    motor.setVelocity(0.0)
speeds = {Keyboard.UP: (6, 6), Keyboard.DOWN: (-6, -6), Keyboard.LEFT: (-3, 3), Keyboard.RIGHT: (3, -3)}
while robot.step(step) != -1:
    keys = []
    key = keyboard.getKey()
    while key != -1:
        keys.append(key)
        key = keyboard.getKey()
    if keys:
        print(f"{robot.getTime():.3f} {keys}")
    l, r = speeds.get(keys[0], (0, 0)) if keys else (0, 0)
    left.setVelocity(l)
    right.setVelocity(r)
"""


def test_key_codes_are_webots_own():
    # cyberbotics/webots include/controller/c/webots/keyboard.h
    assert (Keyboard.END, Keyboard.HOME, Keyboard.LEFT, Keyboard.UP, Keyboard.RIGHT, Keyboard.DOWN) == (
        312, 313, 314, 315, 316, 317)
    assert (Keyboard.PAGEUP, Keyboard.PAGEDOWN) == (366, 367)
    assert (Keyboard.NUMPAD_HOME, Keyboard.NUMPAD_LEFT, Keyboard.NUMPAD_UP, Keyboard.NUMPAD_RIGHT,
            Keyboard.NUMPAD_DOWN, Keyboard.NUMPAD_END) == (375, 376, 377, 378, 379, 382)
    assert (Keyboard.KEY, Keyboard.SHIFT, Keyboard.CONTROL, Keyboard.ALT) == (0xFFFF, 0x10000, 0x20000, 0x40000)


def test_a_script_names_keys_as_webots_codes_them():
    assert keyboard.parse_key("UP") == 315 and keyboard.parse_key("up") == 315
    assert keyboard.parse_key("a") == keyboard.parse_key("A") == 65
    assert keyboard.parse_key("SHIFT+A") == Keyboard.SHIFT + 65
    assert keyboard.parse_key("CONTROL+ALT+DOWN") == Keyboard.CONTROL | Keyboard.ALT | Keyboard.DOWN
    assert keyboard.parse_key("SPACE") == 32 and keyboard.parse_key("+") == ord("+")
    assert keyboard.parse_key("CONTROL++") == Keyboard.CONTROL + ord("+")
    assert keyboard.parse_key("65") == 65 and keyboard.parse_key("7") == ord("7")


def test_terminal_bytes_become_webots_codes():
    assert decode_terminal(b"\x1b[A\x1b[B\x1b[C\x1b[D") == [Keyboard.UP, Keyboard.DOWN, Keyboard.RIGHT, Keyboard.LEFT]
    assert decode_terminal(b"aA ") == [65, Keyboard.SHIFT | 65, 32]
    assert decode_terminal(b"\x1b[1;2A\x1b[1;5D\x1b[5~\x1b[6~\x1b[H\x1bOF") == [
        Keyboard.SHIFT | Keyboard.UP, Keyboard.CONTROL | Keyboard.LEFT, Keyboard.PAGEUP, Keyboard.PAGEDOWN,
        Keyboard.HOME, Keyboard.END]
    assert decode_terminal(b"\x02\r") == [Keyboard.CONTROL | ord("B"), 4]


def test_a_controller_teleoperates_from_a_key_script(controller_file, tmp_path):
    keys = tmp_path / "drive.keys"
    keys.write_text("# forward, turn left, forward, stop\n0 UP\n2.0 LEFT   # a quarter turn or so\n"
                    "2.8 UP\n4.0 -\n")
    status, out, err = run_controller(controller_file(TELEOP), "--keys", str(keys), "--time-limit", "5")
    assert status == 0, err
    lines = out.splitlines()
    # The first sample is one period after enable(); UP is held until 2.0 s, then LEFT.
    assert lines[0] == "0.032 [315]"
    assert "1.984 [315]" in lines and "2.016 [314]" in lines and "2.784 [314]" in lines
    assert "2.816 [315]" in lines and "3.968 [315]" in lines and not any(l.startswith("4.000 ") for l in lines)
    summary = summary_of(out)
    x, y, heading = (float(v) for v in summary["final_pose"].split())
    assert y > 0.5 and x < -0.1  # north first, then north-west after the left turn
    assert 100 < heading < 180


def test_keys_held_together_come_one_a_call_and_sampling_follows_the_period(controller_file, tmp_path):
    source = ("from controller import Robot\nr = Robot()\nk = r.getKeyboard()\nk.enable(64)\n"
              "while r.step(32) != -1:\n    print(f'{r.getTime():.3f}', k.getKey(), k.getKey(), k.getKey())\n"
              "    if r.getTime() > 0.2: break\n")
    keys = tmp_path / "k"
    keys.write_text("0 LEFT SHIFT+X\n")
    status, out, err = run_controller(controller_file(source), "--keys", str(keys))
    assert status == 0, err
    assert out.splitlines()[:4] == [
        "0.032 -1 -1 -1", f"0.064 314 {Keyboard.SHIFT + 88} -1", "0.096 -1 -1 -1", f"0.128 314 {Keyboard.SHIFT + 88} -1"]


def test_without_a_terminal_get_key_returns_minus_one(controller_file):
    source = ("from controller import Robot, Keyboard\nr = Robot()\nk = Keyboard()\nprint(k.getSamplingPeriod())\n"
              "got = set()\nfor _ in range(20):\n    r.step(32)\n    got.add(k.getKey())\nprint(got)\n")
    done = subprocess.run([sys.executable, "-m", "maze_mapper.run", str(controller_file(source))], cwd=REPO,
                          stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[:2] == ["32", "{-1}"]


def test_a_disabled_keyboard_says_so_as_webots_does(controller_file):
    source = "from controller import Robot\nr = Robot()\nr.step(32)\nprint(r.getKeyboard().getKey())\n"
    status, out, err = run_controller(controller_file(source))
    assert status == 0 and out.splitlines()[0] == "-1"
    assert err == "Error: wb_keyboard_get_key() called for a disabled device! Please use: wb_keyboard_enable().\n"


def test_a_bad_key_script_is_named_by_file_line_and_column(controller_file, tmp_path):
    cases = {"0.5 UP\n0.4 DOWN\n": "2:1: error: the time 0.4 s is not after the line before's 0.5 s",
             "0 UP\n1 SHIFT+FOO\n": "2:9: error: unknown key 'FOO'",
             "0 CTRL+A\n": "1:3: error: 'CTRL' is no modifier (SHIFT, CONTROL or ALT)",
             "# nothing\n\n": "1:1: error: the key script holds no line",
             "soon UP\n": "1:1: error: expected a time in seconds, got 'soon'"}
    path = controller_file("print('ran')\n")
    for text, message in cases.items():
        keys = tmp_path / "bad.keys"
        keys.write_text(text)
        status, out, err = run_controller(path, "--keys", str(keys))
        assert status == 2 and out == "", text
        assert err.startswith(f"{keys}:{message}") and err.count("\n") == 1, err


def test_keys_typed_in_a_terminal_reach_the_controller_and_the_terminal_is_restored(controller_file):
    # Each step takes 2 ms of wall-clock time, so the run lasts until the keys come.
    source = ("import time\nfrom controller import Robot\nr = Robot()\nk = r.getKeyboard()\nk.enable(32)\n"
              "print('ready', flush=True)\n"
              "while r.step(32) != -1:\n    time.sleep(0.002)\n    key = k.getKey()\n    if key != -1:\n"
              "        print('key', key, flush=True)\n        if key == 81: break\n")
    master, slave = os.openpty()
    before = termios.tcgetattr(slave)
    process = subprocess.Popen([sys.executable, "-m", "maze_mapper.run", str(controller_file(source)),
                                "--wall-limit", "60"], cwd=REPO, stdin=slave, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    try:
        assert process.stdout.readline() == "ready\n"
        assert not termios.tcgetattr(slave)[3] & termios.ECHO  # keys are read at once, not echoed
        os.write(master, b"\x1b[A")
        assert process.stdout.readline() == f"key {Keyboard.UP}\n"
        os.write(master, b"q")
        assert process.stdout.readline() == "key 81\n"
        out, err = process.communicate(timeout=60)
    finally:
        if process.poll() is None:
            process.kill()
    assert process.returncode == 0, err
    assert termios.tcgetattr(slave) == before
    os.close(master)
    os.close(slave)


def test_the_terminal_is_restored_when_a_signal_stops_the_run(controller_file):
    source = ("import time\nfrom controller import Robot\nr = Robot()\nr.getKeyboard().enable(32)\n"
              "print('ready', flush=True)\nwhile r.step(32) != -1:\n    time.sleep(0.002)\n")
    master, slave = os.openpty()
    before = termios.tcgetattr(slave)
    process = subprocess.Popen([sys.executable, "-m", "maze_mapper.run", str(controller_file(source)),
                                "--wall-limit", "60"], cwd=REPO, stdin=slave, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    try:
        assert process.stdout.readline() == "ready\n"
        assert termios.tcgetattr(slave) != before
        process.terminate()
        out, err = process.communicate(timeout=60)
    finally:
        if process.poll() is None:
            process.kill()
    assert process.returncode == 128 + 15, err
    assert "end: stopped (interrupted by SIGTERM)" in out
    assert termios.tcgetattr(slave) == before
    os.close(master)
    os.close(slave)


def test_the_keyboard_samples_on_after_a_reset_and_the_script_follows_the_time(controller_file, tmp_path):
    source = ("from controller import Supervisor\nr = Supervisor()\nk = r.getKeyboard()\nk.enable(32)\n"
              "for _ in range(10):\n    r.step(32)\nprint(f'{r.getTime():.3f}', k.getKey())\nr.simulationReset()\n"
              "r.step(32)\nr.step(32)\nprint(f'{r.getTime():.3f}', k.getKey())\n")
    keys = tmp_path / "k"
    keys.write_text("0 DOWN\n0.2 UP\n")
    status, out, err = run_controller(controller_file(source), "--keys", str(keys))
    assert status == 0, err
    assert out.splitlines()[:2] == [f"0.320 {Keyboard.UP}", f"0.032 {Keyboard.DOWN}"]
