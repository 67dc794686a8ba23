#!/bin/sh
# Counts past what mms can carry out, in an open 6 x 6 room from (0,0) facing north: each
# answer is checked (a wrong one ends this script with status 3), and the total distance
# must add up without wrapping.
expect() {
  read -r answer
  if [ "$answer" != "$1" ]; then
    echo "huge_counts: $2 answered '$answer', expected '$1'" >&2
    exit 3
  fi
}
echo moveForward 2147483647;  expect crash "moveForward 2147483647"
echo moveForward 1073741824;  expect crash "moveForward 1073741824"
echo moveForward 99999999999; expect crash "moveForward 99999999999"
echo getStat total-distance;  expect 0 "getStat total-distance (nothing moved)"
echo wallFront 2147483647;    expect true "wallFront 2147483647 (the room's north edge)"
echo wallRight 13;            expect true "wallRight 13 (the room's east edge)"
echo moveForward 1073741823;  expect crash "moveForward 1073741823 (north to the edge)"
echo turnRight;               expect ack turnRight
echo turnRight;               expect ack turnRight
echo moveForward 1073741823;  expect crash "moveForward 1073741823 (back south)"
echo getStat total-distance;  expect 2147483646 "getStat total-distance"
