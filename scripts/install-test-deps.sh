#!/bin/sh
# Installs, on top of scripts/install-deps.sh, what the tests that need a browser use:
# Debian's chromium, for tests/replay_chromium.sh (replay.html loaded in headless Chromium).
# maze_mapper itself does not need it; without it that test is skipped, unless
# MAZE_MAPPER_REQUIRE_CHROMIUM is set (.ci/run sets it and runs this script first).
# Also the Python module's build and tests (python/, MAZE_MAPPER_PYTHON): pybind11-dev,
# python3-dev, python3-numpy, python3-pytest.
exec "$(dirname "$0")/install-deps.sh" chromium pybind11-dev python3-dev python3-numpy python3-pytest
