#!/bin/sh
# Misbehaves by the maze's width, for a batch over worlds/: 4 crashes (SIGSEGV), 8 hangs,
# 16 writes garbage, 32 and 5 give up (status 3); 6 (the open room) drives to the centre and exits.
echo mazeWidth
read -r width
case "$width" in
  4) kill -SEGV $$ ;;
  8) sleep 600 ;;
  16) echo "garbage from a confused mouse"; read -r never ;;
  6)
    for move in moveForward moveForward turnRight moveForward moveForward; do
      echo "$move"
      read -r answer
    done
    exit 0 ;;
  *) exit 3 ;;
esac
