#!/usr/bin/env python3
"""Runs every `$ maze_mapper ...` example of a Markdown file and compares what the file shows
with what the program prints, so that the README cannot drift from the program.

In a fenced block, a line `$ maze_mapper ARGS` is a command (a shell line: pipes and
redirections as a reader would type them); the lines after it, up to the next `$ ` line or
the block's end, are its output (standard output and standard error together). A last line
`⋮` means the output goes on: the lines shown must be its start. A block whose first line is
`⋮` continues the previous command's output: its lines must be that output's end.

Each command runs in a fresh folder holding links to the repository's worlds/ and tests/ (so
`worlds/...` reads as in a checkout and files a command writes land there), with
`maze_mapper` first on PATH and no colour. What changes from run to run is masked on both
sides: `wall_time_ms: N`, batch's `ms` column and its run and elapsed times.

Usage: readme_examples.py MAZE_MAPPER SOURCE_DIR [MARKDOWN] (MARKDOWN: SOURCE_DIR/README.md).
Exit status 0 when every example prints what it shows, 1 with a diff of each that does not.
"""

import difflib
import os
import re
import subprocess
import sys
import tempfile

CONTINUES = "⋮"
COMMAND = re.compile(r"^\$ (maze_mapper\b.*)$")
# (pattern, replacement): what varies between runs of the same command.
MASKS = [
    (re.compile(r"wall_time_ms: [0-9.]+"), "wall_time_ms: <ms>"),
    (re.compile(r"run time \d+ ms; elapsed \d+ ms"), "run time <ms> ms; elapsed <ms> ms"),
    # A batch row: world, size, moves, coverage, wall_accuracy, goal, speed_run, ms, end.
    (re.compile(r"^(\S+ +\d+x\d+ +\d+ +\S+ +\S+ +\S+ +\S+) +\d+ +(\S.*)$"), r"\1 <ms> \2"),
]


def masked(lines):
    out = []
    for line in lines:
        for pattern, replacement in MASKS:
            line = pattern.sub(replacement, line)
        out.append(line.rstrip())
    return out


class Example:
    def __init__(self, line_number, command):
        self.line_number = line_number  # of the `$ ` line, from 1
        self.command = command
        self.head = []  # the output's first lines as shown
        self.head_is_prefix = False  # the shown head ends with ⋮
        self.tail = []  # the output's last lines, from a block starting with ⋮


def examples(markdown):
    """The examples of the file, in order."""
    found = []
    in_block = False
    block_start = False
    current = None  # the example whose output the lines are
    continuing = None  # the example a ⋮ block continues
    for number, line in enumerate(markdown.splitlines(), start=1):
        if line.startswith("```"):
            in_block = not in_block
            block_start = in_block
            if not in_block:
                current = None
                continuing = None
            continue
        if not in_block:
            continue
        first_of_block = block_start
        block_start = False
        match = COMMAND.match(line)
        if match:
            current = Example(number, match.group(1))
            continuing = None
            found.append(current)
        elif first_of_block and line.strip() == CONTINUES and found:
            continuing = found[-1]
        elif continuing is not None:
            continuing.tail.append(line)
        elif current is not None:
            if line.strip() == CONTINUES:
                current.head_is_prefix = True
            elif current.head_is_prefix:
                raise SystemExit(f"line {number}: output after {CONTINUES}; start a new block with {CONTINUES}")
            else:
                current.head.append(line)
    return found


def run(example, program, source):
    with tempfile.TemporaryDirectory(prefix="maze_mapper_readme_") as folder:
        for name in ("worlds", "tests"):
            os.symlink(os.path.join(source, name), os.path.join(folder, name))
        env = dict(os.environ)
        env["PATH"] = os.path.dirname(os.path.abspath(program)) + os.pathsep + env.get("PATH", "")
        env["NO_COLOR"] = "1"
        env.pop("MAZE_MAPPER_WORLDS", None)
        env.pop("COLUMNS", None)
        ran = subprocess.run(["sh", "-c", example.command], cwd=folder, env=env, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, timeout=600)
        return ran.stdout.decode("utf-8", errors="replace").splitlines()


def differences(example, printed):
    """A diff of what the example shows against what was printed; empty when they agree."""
    printed = masked(printed)
    shown_head = masked(example.head)
    shown_tail = masked(example.tail)
    got_head = printed[:len(shown_head)] if example.head_is_prefix or example.tail else printed
    got_tail = printed[len(printed) - len(shown_tail):] if shown_tail else []
    diff = []
    for shown, got, part in ((shown_head, got_head, "start"), (shown_tail, got_tail, "end")):
        if shown != got:
            diff += difflib.unified_diff(shown, got, f"README (the output's {part})", "the program", lineterm="")
    return diff


def main():
    if len(sys.argv) not in (3, 4):
        raise SystemExit(__doc__.split("\n\n")[-2])
    program, source = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    markdown_path = sys.argv[3] if len(sys.argv) == 4 else os.path.join(source, "README.md")
    with open(markdown_path, encoding="utf-8") as f:
        found = examples(f.read())
    if not found:
        raise SystemExit(f"{markdown_path}: no `$ maze_mapper` example")
    failed = 0
    for example in found:
        diff = differences(example, run(example, program, source))
        if diff:
            failed += 1
            print(f"{markdown_path}:{example.line_number}: the example's output differs: $ {example.command}")
            print("\n".join(diff))
        else:
            print(f"{markdown_path}:{example.line_number}: ok: $ {example.command}")
    print(f"{len(found)} examples, {failed} differ")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
