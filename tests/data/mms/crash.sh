#!/bin/sh
# Asks one question, then dies of a segmentation fault.
echo mazeWidth
read -r width
kill -SEGV $$
