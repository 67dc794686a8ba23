#!/bin/sh
# Starts a child in a session of its own (setsid) that keeps our output open and sleeps,
# writes that child's pid to $MMS_TEST_PIDFILE, then exits at once without a word.
setsid sh -c 'echo $$ >"$MMS_TEST_PIDFILE"; exec sleep 600' &
while [ ! -s "$MMS_TEST_PIDFILE" ]; do sleep 0.01; done
exit 0
