#!/bin/bash
# scripts/exercise.sh — build the exercises of exercises/ and check them with
# the suite's own measurements.
#
#   bash scripts/exercise.sh NAME          one exercise: each check with the value
#                                          measured, the one expected, pass or FAIL;
#                                          the picture build/exercises/NAME.png
#   bash scripts/exercise.sh --all         every exercise, then a table (for grading)
#   bash scripts/exercise.sh --solutions   the suite's own solutions, same checks
#
# Exit status: 0 when every check passes, 1 when one fails, 2 when the code
# does not build (the compiler's first error is printed, nothing else) or
# the command is wrong.  Each exercise runs in a process of its own, with a
# time limit (10 s): a crash, an endless loop or a NaN fails that exercise
# in one line, and the next one is checked.
set -u
cd "$(dirname "$0")/.."
case "${1:-}" in
  "" | -h | --help)
    sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'
    [ -n "${1:-}" ] && exit 0 || exit 2 ;;
esac
log=$(mktemp)
trap 'rm -f "$log"' EXIT
if [ ! -f build/CMakeCache.txt ] && ! cmake --preset default >"$log" 2>&1; then
  echo "exercise.sh: cannot configure the build (cmake --preset default); run bash scripts/setup.sh first" >&2
  exit 2
fi
if ! cmake --build --preset default --target exercise_check >"$log" 2>&1; then
  # The first error, in the student's file if it is there.
  first=$(grep -m1 -E '^[^ ]*exercises/[^:]+:[0-9]+(:[0-9]+)?: (fatal )?error' "$log")
  [ -z "$first" ] && first=$(grep -m1 -E '(fatal )?error' "$log")
  echo "${first#"$PWD/"}"
  exit 2
fi
case "$1" in
  --all) exec build/bin/exercise_check --all ;;
  --solutions) exec build/bin/exercise_check --all --solutions ;;
  *) exec build/bin/exercise_check "$@" ;;
esac
