#!/bin/sh
# In wall_ahead6x6 (an open 6 x 6 room, a wall on the north side of (0,3)) from (0,0) facing
# north: moveForward 5 stops before the wall and answers crash, the wall is then ahead, and
# mms's distance counts the 5 asked. A wrong answer ends this script with status 3.
expect() {
  read -r answer
  if [ "$answer" != "$1" ]; then
    echo "wall_ahead: $2 answered '$answer', expected '$1'" >&2
    exit 3
  fi
}
echo "moveForward 5";          expect crash "moveForward 5 (a wall three cells on)"
echo wallFront;                expect true "wallFront (after the crash)"
echo "getStat total-distance"; expect 5 "getStat total-distance"
