#!/bin/sh
# Writes one endless line.
yes x | tr -d '\n'
