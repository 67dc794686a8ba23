#!/bin/sh
# Drives north from (0,0) of an open 6 x 6 room toward its centre, then loops asking
# wasReset for ever (as mms's templates do): --until goal must end it.
echo moveForward; read -r a
echo moveForward; read -r a
echo turnRight; read -r a
echo moveForward; read -r a
echo moveForward; read -r a
while :; do echo wasReset; read -r a || exit 0; done
