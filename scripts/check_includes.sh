#!/bin/sh
# Every source file of the program and of the Python module compiles on its own. The
# presets build in unity mode (CMAKE_UNITY_BUILD), where a file that forgets an include still
# compiles when an earlier file of its batch has it; a plain `cmake -S . -B build` then fails.
# This configures a build without unity mode (configure only: seconds), then runs each
# translation unit's own compile command, outside tests/, with -fsyntax-only, JOBS at a time,
# and fails naming the files that do not compile, with their first error. The compiler is
# clang++ when there is one: it parses these files in about two thirds of g++'s time, over
# the same libstdc++ headers, so an include missing for one is missing for the other.
#   usage: scripts/check_includes.sh [SOURCE_DIR] [JOBS]
set -eu
source_dir=$(cd "${1:-$(dirname "$0")/..}" && pwd)
jobs=${2:-2}
build="$source_dir/build/check-includes"  # configured again each time; nothing is compiled into it
mkdir -p "$build"
compiler=$(command -v clang++ || command -v c++)
cmake -S "$source_dir" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER="$compiler" -DCMAKE_UNITY_BUILD=OFF -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DMAZE_MAPPER_PYTHON=AUTO \
  >"$build/configure.log" 2>&1 || { cat "$build/configure.log"; exit 1; }
python3 - "$build/compile_commands.json" "$source_dir" "$jobs" <<'PY'
import json, shlex, subprocess, sys
from concurrent.futures import ThreadPoolExecutor

entries, source, jobs = json.load(open(sys.argv[1])), sys.argv[2] + "/", int(sys.argv[3])
units = [e for e in entries
         if e["file"].startswith(source) and not e["file"][len(source):].startswith(("tests/", "build/"))]

def check(entry):
    words = shlex.split(entry["command"])
    if "-o" in words:  # -fsyntax-only writes no object
        del words[words.index("-o"):words.index("-o") + 2]
    done = subprocess.run(words + ["-fsyntax-only"], cwd=entry["directory"], capture_output=True, text=True)
    first_error = next((line for line in done.stderr.splitlines() if "error" in line), done.stderr.strip()[:300])
    return None if done.returncode == 0 else f"{entry['file'][len(source):]}: {first_error}"

with ThreadPoolExecutor(jobs) as pool:
    failed = [f for f in pool.map(check, units) if f]
if failed:
    print("check_includes: these do not compile on their own (a missing include?):")
    print("\n".join(failed))
    sys.exit(1)
print(f"check_includes: {len(units)} translation units compile on their own")
PY
