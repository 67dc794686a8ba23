#!/bin/sh
# Rewrites every golden file under tests/golden from the current build, then shows what
# changed. Read the diff before committing: a golden file is an assertion.
set -eu
cd "$(dirname "$0")/.."
preset="${1:-release}"
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset"
MAZE_MAPPER_UPDATE_GOLDEN=1 ctest --preset "$preset" -L golden --output-on-failure
git status --short tests/golden
git --no-pager diff --stat tests/golden
