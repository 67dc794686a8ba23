#!/bin/sh
# Asks one question, then writes a line that is no command.
echo mazeWidth
read -r width
echo "hello, simulator"
read -r never
