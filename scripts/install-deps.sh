#!/bin/sh
# Installs the Debian 12 packages building and running maze_mapper needs, and any further
# package names given as arguments (scripts/install-test-deps.sh and
# scripts/install-bench-deps.sh pass their own). Nothing here is for the tests alone.
# Idempotent: packages already present are left alone and apt is not called.
set -eu

PACKAGES="cmake ninja-build g++ \
libeigen3-dev libfmt-dev libcli11-dev libexpat1-dev libpng-dev nlohmann-json3-dev \
pkg-config libcairo2-dev fonts-dejavu-core $*"

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
