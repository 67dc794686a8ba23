#!/bin/bash
# The Debian package as a teacher hands it out, on this machine (root; CI's own Debian 12):
# CPack builds maze_mapper_VERSION_ARCH.deb from a release build, `apt install` installs it,
# the program maps its default world and a shipped one by its name from another directory, `man` shows
# every command, bash completes `maze_mapper run --rob` to --robot, python3 imports the module
# (as root, so Python writes __pycache__ beside it), and removing the package leaves nothing
# under /usr that was not there before. lintian finds no error and no warning in it. Needs
# dpkg-dev, file, man-db and lintian (scripts/install-test-deps.sh). Usage: tests/package_deb.sh [BUILD_DIR] (build/release).
set -euo pipefail
build=$(realpath "${1:-build/release}")
package=maze-mapper
fail() { echo "FAIL: $*" >&2; exit 1; }

[ "$(id -u)" -eq 0 ] || fail "needs root (apt install)"
if dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    fail "$package is installed already; remove it first (apt remove $package)"
fi
work=$(mktemp -d)
installed=0
# A failing check still removes the package it installed (the machine is left as found).
cleanup() {
    if [ "$installed" -eq 1 ]; then
        DEBIAN_FRONTEND=noninteractive apt-get remove -y -qq --purge "$package" > /dev/null 2>&1 || true
    fi
    rm -rf "$work"
}
trap cleanup EXIT

rm -f "$build"/maze_mapper_*.deb
(cd "$build" && cpack -G DEB > "$work/cpack.log") || { cat "$work/cpack.log" >&2; fail "cpack"; }
deb=$(ls "$build"/maze_mapper_*.deb)
echo "package: $deb"
depends=$(dpkg-deb -f "$deb" Depends)
echo "depends: $depends"
for needed in libcairo2 fonts-dejavu-core; do
    grep -q "$needed" <<< "$depends" || fail "the package does not depend on $needed (the pictures)"
done
recommends=$(dpkg-deb -f "$deb" Recommends)
echo "recommends: $recommends"
grep -qF bash-completion <<< "$recommends" || fail "the package does not recommend bash-completion (bash completes nothing without it)"
python_module=$(dpkg-deb -c "$deb" | awk '{ print $6 }' | grep '/maze_mapper/__init__.py$' || true)
if [ -n "$python_module" ]; then
    [ "$python_module" = ./usr/lib/python3/dist-packages/maze_mapper/__init__.py ] ||
        fail "the Python module is at $python_module, not in /usr/lib/python3/dist-packages"
    for needed in 'python3 (>=' python3-numpy; do
        grep -qF "$needed" <<< "$depends" || fail "the package has the Python module but no Depends on $needed"
    done
    for wanted in python3-pandas python3-matplotlib; do
        grep -qF "$wanted" <<< "$recommends" || fail "the package has the Python module but does not recommend $wanted (the course's library imports it)"
    done
fi

# Every lintian error (E:) and warning (W:) fails; the informational tags (I:, N:) do not.
# Run as root, lintian says so: --allow-root.
lintian --allow-root --no-tag-display-limit "$deb" > "$work/lintian.out" 2>&1 || true
if grep -E '^(E|W): ' "$work/lintian.out" >&2; then
    fail "lintian: $(grep -cE '^(E|W): ' "$work/lintian.out") errors and warnings"
fi
echo "lintian: no error, no warning"

find /usr -xdev | sort > "$work/before"
export DEBIAN_FRONTEND=noninteractive
installed=1
apt-get install -y -qq --no-install-recommends "$deb" > "$work/apt.log" 2>&1 || { cat "$work/apt.log" >&2; fail "apt install"; }
dpkg -L "$package" > "$work/files"

cd "$work"  # under /tmp: no worlds/ here
maze_mapper > "$work/main.out" || fail "maze_mapper from /tmp exited $?"
grep -q '^world: /usr/share/maze_mapper/worlds/lab4x4.txt$' "$work/main.out" || fail "the default world: $(grep '^world:' "$work/main.out")"
grep -q '^end: done$' "$work/main.out" || fail "the default world was not mapped: $(grep '^end:' "$work/main.out")"
maze_mapper run maze8x8 --quiet > "$work/run.out" || fail "run maze8x8 exited $?"
grep -q '^world: /usr/share/maze_mapper/worlds/maze8x8.txt$' "$work/run.out" || fail "run maze8x8: $(grep '^world:' "$work/run.out")"
grep -q '^end: done$' "$work/run.out" || fail "maze8x8 was not mapped"
maze_mapper worlds | grep -q '^maze8x8.txt  *maze   8 x 8 cells$' || fail "maze_mapper worlds does not list maze8x8.txt"
echo "ran: maze_mapper, maze_mapper run maze8x8 (a shipped world by its name; end: done), maze_mapper worlds"

# Every command --help lists, and every one those list (demo 1d, batch merge), in the man page.
MANPAGER=cat MANWIDTH=80 man maze_mapper > "$work/man.txt" 2> "$work/man.err" || { cat "$work/man.err" >&2; fail "man maze_mapper"; }
commands() { "$@" --help | sed -n '/^Commands:/,/^$/p' | awk '/^  [^ ]/ { print $1 }'; }
names=()
for command in $(commands maze_mapper); do
    names+=("$command")
    for sub in $(commands maze_mapper "$command"); do names+=("$command $sub"); done
done
checked=0
for heading in "${names[@]}"; do
    grep -q "^   $heading\$" "$work/man.txt" || fail "man maze_mapper has no section for '$heading'"
    checked=$((checked + 1))
done
[ "$checked" -gt 10 ] || fail "only $checked commands found in --help"
echo "man: a section for each of $checked commands"

completion=/usr/share/bash-completion/completions/maze_mapper
grep -qx "$completion" "$work/files" || fail "no bash completion installed"
# shellcheck disable=SC2016
got=$(bash -c 'source "$1"; COMP_WORDS=(maze_mapper run --rob); COMP_CWORD=2; _maze_mapper; echo "${COMPREPLY[*]}"' _ "$completion")
[ "$got" = "--robot" ] || fail "bash completes 'maze_mapper run --rob' to '$got'"
for f in /usr/share/zsh/vendor-completions/_maze_mapper /usr/share/fish/vendor_completions.d/maze_mapper.fish \
         /usr/share/doc/maze-mapper/README.md /usr/share/doc/maze-mapper/copyright \
         /usr/share/doc/maze-mapper/changelog.Debian.gz /usr/share/maze_mapper/worlds/lab4x4.txt; do
    grep -qx "$f" "$work/files" || fail "$f is not in the package"
done
echo "completion: bash completes 'maze_mapper run --rob' to --robot; zsh and fish installed"
# As a user's interactive bash has it with bash-completion (which the package recommends): the
# completion loaded on first use, `complete -p maze_mapper` set, --strategy's words offered.
if [ -f /usr/share/bash-completion/bash_completion ]; then
    # shellcheck disable=SC2016
    got=$(bash -c '. /usr/share/bash-completion/bash_completion; _completion_loader maze_mapper; complete -p maze_mapper
                   COMP_WORDS=(maze_mapper run --strategy fl); COMP_CWORD=3; _maze_mapper; echo "${COMPREPLY[*]}"')
    case "$got" in
        "complete -o filenames -F _maze_mapper maze_mapper"*floodfill*) ;;
        *) fail "with bash-completion, complete -p maze_mapper and run --strategy fl<TAB> give '$got'" ;;
    esac
    echo "completion: with bash-completion, complete -p maze_mapper is set and --strategy fl completes to floodfill"
fi

if [ -n "$python_module" ]; then
    (cd / && env -u PYTHONPATH -u PYTHONDONTWRITEBYTECODE /usr/bin/python3 -c 'import maze_mapper, numpy; print(maze_mapper.__file__)') > "$work/python.out" ||
        fail "python3 cannot import the installed module"
    grep -qx /usr/lib/python3/dist-packages/maze_mapper/__init__.py "$work/python.out" ||
        fail "python3 imported maze_mapper from $(cat "$work/python.out")"
    [ -d /usr/lib/python3/dist-packages/maze_mapper/__pycache__ ] ||
        fail "python3 wrote no __pycache__ beside the module (what the package's prerm removes)"
    echo "python: import maze_mapper from /usr/lib/python3/dist-packages (its __pycache__ written)"
fi

# apt remove (not --purge), what a teacher types; the prerm takes Python's __pycache__ away.
apt-get remove -y -qq "$package" > "$work/apt.log" 2>&1 || { cat "$work/apt.log" >&2; fail "apt remove"; }
installed=0
find /usr -xdev | sort > "$work/after"
if ! diff "$work/before" "$work/after" > "$work/diff"; then
    cat "$work/diff" >&2
    fail "removing $package left /usr changed"
fi
echo "removed: /usr as before the install"
