#!/usr/bin/env bash
# tests/valgrind/run.sh [MAKE_FIGURES] [make_figures args...] — one full
# figure regeneration under valgrind memcheck, into a temporary folder.
# Passes when memcheck reports no invalid read or write, no use of
# uninitialised values in the project's code, and no definite leak outside
# Mesa (tests/valgrind/mesa.supp suppresses Mesa's, by library).
# LP_NUM_THREADS=0: llvmpipe renders on the calling thread (memcheck
# serialises threads anyway; this also makes the run deterministic).
set -euo pipefail
cd "$(dirname "$0")/../.."
FIGS=${1:-build-rel/bin/make_figures}
shift || true
[ -x "$FIGS" ] || { echo "valgrind/run.sh: build $FIGS first (e.g. cmake --build build-rel --target make_figures)"; exit 2; }
command -v valgrind >/dev/null || { echo "valgrind/run.sh: valgrind is not installed (Debian: valgrind)"; exit 2; }
OUT=$(mktemp -d "${TMPDIR:-/tmp}/ts_valgrind.XXXXXX")
LOG="$OUT.log"
trap 'rm -rf "$OUT"' EXIT
set +e
LP_NUM_THREADS=0 valgrind --tool=memcheck --error-exitcode=9 --leak-check=full --show-leak-kinds=definite \
  --errors-for-leak-kinds=definite --track-origins=no --num-callers=30 \
  --suppressions=tests/valgrind/mesa.supp --log-file="$LOG" \
  "$FIGS" --backend osmesa --out "$OUT" "$@" >/dev/null
rc=$?
grep -E "ERROR SUMMARY|definitely lost|indirectly lost|Invalid (read|write)|uninitialised" "$LOG" | sort | uniq -c | head -20
echo "full log: $LOG"
exit $rc
