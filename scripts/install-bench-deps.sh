#!/bin/sh
# Installs the Debian 12 packages the benchmarks need on top of scripts/install-deps.sh:
# OctoMap (the library bench_ray_integration compares against), the `time` program
# (bench/scale.sh) and perf/valgrind for profiling. maze_mapper itself needs none of them.
# Idempotent: packages already present are left alone and apt is not called.
set -eu

PACKAGES="liboctomap-dev time linux-perf valgrind"

missing=""
for pkg in $PACKAGES; do
    if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
        missing="$missing $pkg"
    fi
done

if [ -z "$missing" ]; then
    exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
    echo "error: missing packages:$missing (run this script as root, or install them)" >&2
    exit 2
fi

echo "installing:$missing"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
# shellcheck disable=SC2086
apt-get install -y -qq --no-install-recommends $missing >/dev/null
