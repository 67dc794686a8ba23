#!/bin/sh
# Installs, on top of scripts/install-deps.sh, what the tests and CI need; maze_mapper itself
# needs none of it:
#   doctest-dev                 the unit tests (without it the release preset builds no tests)
#   clang libclang-rt-14-dev    the fuzz preset: the sanitizer build of the suite and libFuzzer
#   universal-ctags             style/sizes (scripts/check_sizes.sh)
#   tmux                        animate_tmux (--animate in a real terminal)
#   chromium                    replay_chromium (replay.html in headless Chromium; skipped
#                               without it unless MAZE_MAPPER_REQUIRE_CHROMIUM is set, as
#                               .ci/run does)
#   dpkg-dev file man-db        the Debian package stage (tests/package_deb.sh): CPack's
#   lintian                     dpkg-shlibdeps and file, `man` to read the installed page, and
#                               lintian to check the package (no error, no warning)
#   python3                     the example mms algorithm in Python (tests/mms_examples.sh)
#   pybind11-dev python3-dev    the Python module (python/, MAZE_MAPPER_PYTHON) and its tests
#   python3-numpy python3-pytest
#   slurmctld slurmd            python/slurm_grade: a class graded by a one-node Slurm job
#   slurm-client munge parallel array and by GNU parallel (skipped without them)
#   bash-completion             the package stage: `complete -p maze_mapper` once installed
# Further package names given as arguments are installed too.
exec "$(dirname "$0")/install-deps.sh" doctest-dev clang libclang-rt-14-dev universal-ctags tmux chromium \
    dpkg-dev file man-db lintian \
    python3 pybind11-dev python3-dev python3-numpy python3-pytest \
    slurmctld slurmd slurm-client munge parallel bash-completion "$@"
