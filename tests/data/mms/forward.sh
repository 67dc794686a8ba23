#!/bin/sh
# One moveForward a word given, with that count: `forward.sh 5` drives five cells in one
# command, `forward.sh 1 1 1 1 1` the same five one at a time; then exits.
for n in "$@"; do echo "moveForward $n"; read -r a; done
