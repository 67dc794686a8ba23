#!/bin/sh
# Asks one question, then hangs without a word, in a child of its own (as a stuck program
# that started one would); that child's pid goes to $MMS_TEST_PIDFILE when set.
echo mazeWidth
read -r width
sleep 600 &
echo $! > "${MMS_TEST_PIDFILE:-/dev/null}"
wait
