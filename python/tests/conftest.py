"""What the Python tests share: where the program, the worlds and the examples are (CTest
passes them, python/CMakeLists.txt), and running a controller under maze_mapper.run."""

import os
import subprocess
import sys

import pytest

PROGRAM = os.environ.get("MAZE_MAPPER_PROGRAM", "")
WORLDS = os.environ.get("MAZE_MAPPER_WORLDS_DIR", "")
EXAMPLES = os.environ.get("MAZE_MAPPER_EXAMPLES_DIR", "")
REPO = os.path.dirname(WORLDS)


def world(name):
    return os.path.join(WORLDS, name)


def program(*args, check=True):
    """Runs the maze_mapper program from the top of the repository; (status, stdout, stderr)."""
    done = subprocess.run([PROGRAM, *args], cwd=REPO, capture_output=True, text=True)
    if check:
        assert done.returncode == 0, done.stderr
    return done.returncode, done.stdout, done.stderr


def run_controller(path, *args, cwd=None, env=None, timeout=300):
    """python3 -m maze_mapper.run PATH ARGS...; (status, stdout, stderr)."""
    done = subprocess.run([sys.executable, "-m", "maze_mapper.run", str(path), *args],
                          cwd=cwd or REPO, capture_output=True, text=True, timeout=timeout, env=env)
    return done.returncode, done.stdout, done.stderr


def temporaries_under(folder):
    """The .NAME.tmp.PID files left anywhere under a folder."""
    return [os.path.join(d, f) for d, _, files in os.walk(folder) for f in files if ".tmp." in f]


def summary_of(text):
    """The `key: value` lines after the last blank line."""
    block = text.rstrip("\n").split("\n\n")[-1]
    return dict(line.split(": ", 1) for line in block.splitlines() if ": " in line)


def final_map(text, rows):
    """The map printed before the summary: the `rows` lines before its blank line."""
    lines = text.rstrip("\n").split("\n\n")[-2].split("\n")
    return "\n".join(lines[-rows:]) + "\n"


@pytest.fixture
def controller_file(tmp_path):
    """Writes a controller's source to a file; returns its path."""
    def write(source, name="my_controller.py"):
        path = tmp_path / name
        path.write_text(source)
        return path
    return write



def png_pixels(data):
    """A PNG's pixels as a NumPy array (height, width, 3), rows top first: 8-bit RGB or RGBA,
    not interlaced, filters None and Up (as the program writes them)."""
    import struct
    import zlib
    import numpy as np
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    at, idat = 8, b""
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    bpp = 4 if colour == 6 else 3
    raw = np.frombuffer(zlib.decompress(idat), dtype=np.uint8).reshape(height, width * bpp + 1)
    rows = np.zeros((height, width * bpp), dtype=np.uint8)
    previous = np.zeros(width * bpp, dtype=np.uint8)
    for y in range(height):
        assert raw[y, 0] in (0, 2), f"filter {raw[y, 0]}"
        rows[y] = raw[y, 1:] + (previous if raw[y, 0] == 2 else 0)
        previous = rows[y]
    return rows.reshape(height, width, bpp)[:, :, :3]
