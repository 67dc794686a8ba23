#!/bin/sh
# Installs, on top of scripts/install-deps.sh, what some tests use: Debian's chromium, for
# tests/replay_chromium.sh (replay.html loaded in headless Chromium), and python3, for the
# example mms algorithm in Python (tests/mms_examples.sh). maze_mapper itself needs neither;
# without chromium that test is skipped, unless MAZE_MAPPER_REQUIRE_CHROMIUM is set (.ci/run
# sets it and runs this script first); without python3 the examples test is not registered.
exec "$(dirname "$0")/install-deps.sh" chromium python3
