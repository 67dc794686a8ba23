#!/bin/sh
# Asks for a stat mms does not have (mms drops the line and answers nothing), then asks a
# real one and exits 0 when it is answered.
echo getStat foo
echo getStat total-turns
read -r turns
[ "$turns" = 0 ] || exit 3
