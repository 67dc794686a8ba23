#!/bin/sh
# scripts/course-venv.sh VENV: maze_mapper in a course's virtual environment, from this checkout,
# offline. Reuses build/release when it holds the module (the README's build), else builds the
# module's target there first, showing the build's progress (a full build from source takes
# 15-30 min on two busy cores); then links VENV to it (python3 -m maze_mapper.venv: a .pth file,
# VENV created when missing). After the Debian package, `python3 -m maze_mapper.venv VENV` alone
# does it.
set -eu
if [ $# -ne 1 ]; then
  echo "usage: scripts/course-venv.sh VENV" >&2
  exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build/release"
python=/usr/bin/python3
[ -x "$python" ] || python=python3
if [ ! -f "$build/CMakeCache.txt" ]; then
  echo "configuring $build (cmake --preset release)" >&2
  (cd "$root" && cmake --preset release -DPython3_EXECUTABLE="$python" >/dev/null)
fi
# Ninja prints [N/M] as it goes: the progress of a build from source; nothing to do is one line.
echo "building the module (cmake --build $build --target maze_mapper_native)" >&2
nice -n 10 cmake --build "$build" --target maze_mapper_native >&2
PYTHONPATH="$build/python" exec "$python" -m maze_mapper.venv "$1"
