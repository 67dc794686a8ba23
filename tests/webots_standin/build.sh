#!/bin/bash
# CI: builds the Webots controller (MAZE_MAPPER_WEBOTS=ON, warnings as errors) against a
# stand-in WEBOTS_HOME, installs it as Webots expects (controllers/<name>/<name>) and runs it
# once, so that the real-Webots configuration cannot rot without a Webots install.
#
# The stand-in WEBOTS_HOME (in OUT, default build/webots-standin):
#   include/controller/cpp/webots/*.hpp   the project's webots:: headers (maze/webots/include),
#                                         API-identical to Webots' own for what the controller
#                                         uses, plus traps.hpp: Webots' warning patterns, so the
#                                         build fails unless Webots' folders are SYSTEM includes
#   include/controller/c/webots/types.h   what Webots' C++ headers include from the C API
#   lib/controller/libCppController.so    CppController.cpp: a robot with no devices whose
#   lib/controller/libController.so       simulation has ended; an empty C library
# The configure needs only what the controller links (Eigen, fmt): no CLI11, libpng,
# expat or nlohmann-json.
set -euo pipefail
cd "$(dirname "$0")/../.."
out=$(realpath -m "${1:-build/webots-standin}")
home=$out/webots_home
here=tests/webots_standin

rm -rf "$home" "$out/project"
mkdir -p "$home/include/controller/cpp/webots" "$home/include/controller/c/webots" "$home/lib/controller"
cp maze/webots/include/webots/*.hpp "$home/include/controller/cpp/webots/"
cp "$here/types.h" "$home/include/controller/c/webots/types.h"
cat "$here/traps.hpp" >> "$home/include/controller/cpp/webots/Device.hpp"

echo "== the traps trip our warnings when the headers are not SYSTEM includes"
if echo '#include <webots/Device.hpp>' |
    c++ -std=c++20 -fsyntax-only -Wextra -Wshadow -Werror -I"$home/include/controller/cpp" -x c++ - 2>/dev/null; then
  echo "error: the stand-in's traps.hpp no longer trips -Wshadow / -Wignored-qualifiers" >&2
  exit 1
fi

echo "== the stand-in libraries"
c++ -std=c++20 -O0 -shared -fPIC -I"$home/include/controller/cpp" "$here/CppController.cpp" \
  -o "$home/lib/controller/libCppController.so"
echo 'int maze_mapper_standin_controller;' | cc -shared -fPIC -x c - -o "$home/lib/controller/libController.so"

echo "== configure and build with MAZE_MAPPER_WEBOTS=ON, warnings as errors"
cmake -S . -B "$out/build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O0 \
  -DMAZE_MAPPER_WEBOTS=ON -DWEBOTS_HOME="$home" -DMAZE_MAPPER_WERROR=ON > "$out/configure.log"
cmake --build "$out/build" -j2
cmake --install "$out/build" --prefix "$out/project" > /dev/null

exe=$out/project/controllers/maze_mapper_controller/maze_mapper_controller
echo "== run $exe"
expect() {  # expect STATUS STDERR ARGS...: the run's exit status and its one line on stderr
  local status=$1 message=$2
  shift 2
  local got=0
  "$exe" "$@" > "$out/run.out" 2> "$out/run.err" || got=$?
  if [ "$got" -ne "$status" ] || [ "$(cat "$out/run.err")" != "$message" ]; then
    echo "error: maze_mapper_controller $*: exit $got, stderr '$(cat "$out/run.err")'; expected exit $status, '$message'" >&2
    exit 1
  fi
}
expect 2 "error: controller argument '--size=4': expected WxH, e.g. 4x4" --size=4
expect 2 'error: the robot has no device "left motor"' --size=4x4 --cell-size=0.5
echo "ok: the Webots controller builds with -Werror against the stand-in, installs and runs"
