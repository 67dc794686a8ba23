#!/bin/sh
# The conversation of mms's README example (its "Example" table), unchanged, on a classic
# 16 x 16 maze: each answer is checked; a wrong one ends this script with status 3.
expect() {
  read -r answer
  if [ "$answer" != "$1" ]; then
    echo "readme_conversation: $2 answered '$answer', expected '$1'" >&2
    exit 3
  fi
}
echo mazeWidth;           expect 16 mazeWidth
echo mazeWidth;           expect 16 mazeWidth
echo wallLeft;            expect true wallLeft
echo setWall 0 0 W
echo wallFront;           expect false wallFront
echo moveForward;         expect ack moveForward
echo turnLeft;            expect ack turnLeft
echo wallFront;           expect true wallFront
echo moveForward;         expect crash moveForward
echo setColor 0 1 r
echo setText 0 1 whoops
echo wasReset;            expect false wasReset
echo clearAllColor
echo clearAllText
echo ackReset;            expect ack ackReset
echo getStat total-distance; expect 1 getStat
echo getStat best-run-turns; expect -1 getStat
echo getStat score;       expect 2000 getStat
