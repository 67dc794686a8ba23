#!/bin/bash
# The generated bash completion (app/cli/cli_reference.hpp) completes as a user types: the
# command after `maze_mapper`, an option of the command typed (`run --rob` -> --robot), a
# nested command's option (`batch merge -`), files after an option taking a value, the words of
# --strategy, --model, --robot and --color (and no file there), and shipped worlds' names.
# Usage: completion_bash.sh BASH_COMPLETION_FILE
set -uo pipefail  # no -e: compgen fails when nothing matches, as bash expects
# shellcheck disable=SC1090
source "$1"
fail=0
completes() {  # completes EXPECTED WORD...: the completion of the last word includes EXPECTED
    local expected=$1
    shift
    COMP_WORDS=(maze_mapper "$@")
    COMP_CWORD=$#
    COMPREPLY=()
    _maze_mapper
    if [[ " ${COMPREPLY[*]} " != *" $expected "* ]]; then
        echo "FAIL: maze_mapper $* -> '${COMPREPLY[*]}', not $expected" >&2
        fail=1
    fi
}
completes --robot run --rob
completes run ru
completes merge batch me
completes --help batch merge --he
completes 1d demo 1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
touch my_maze.txt
completes my_maze.txt run --out here my_
completes my_maze.txt run my_
completes floodfill run --strategy fl
completes dfs run --strategy ""
completes hambot run --robot ham
completes never run --color n
completes pie run --model p
completes maze8x8 run maze
completes lab4x4 batch la
offers_no() {  # offers_no WORD ARG...: the completion of the last word does not offer WORD
    local unwanted=$1
    shift
    COMP_WORDS=(maze_mapper "$@")
    COMP_CWORD=$#
    COMPREPLY=()
    _maze_mapper
    if [[ " ${COMPREPLY[*]} " == *" $unwanted "* ]]; then
        echo "FAIL: maze_mapper $* -> '${COMPREPLY[*]}' offers $unwanted" >&2
        fail=1
    fi
}
offers_no my_maze.txt run --strategy ""
offers_no my_maze.txt run --robot ""
offers_no maze8x8 run --out ""
exit $fail
