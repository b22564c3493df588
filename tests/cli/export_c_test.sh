#!/usr/bin/env bash
# tests/cli/export_c_test.sh FIRST_RUN RELIABILITY_TOOL DEMO_BIN_DIR — every
# book figure exported as a standalone C program (--export-c):
#   1. each builds with the system C compiler both ways, warnings as errors:
#        cc -std=c99 -Wall -Werror FILE.c -o fig -lglfw -lGL -lm          (a window)
#        cc -std=c99 -Wall -Werror -DOFFSCREEN FILE.c -o fig -lOSMesa -lm (no GLFW, no libGL)
#   2. the offscreen build's picture (./fig out.ppm) is the demo's own render
#      of the same state (make_figures' PNG, OSMesa), within the bounds of
#      its export_bound row in demos/*/facts.tsv (measured; a figure without
#      one must match exactly);
#   3. a state that cannot be exported (the parallax live view draws a texture
#      it rendered itself) says so in one line, exits 2 and writes nothing.
# Two compilations run at a time (2 cores).
set -u
FIRST=$(readlink -f "${1:?usage: export_c_test.sh FIRST_RUN RELIABILITY_TOOL DEMO_BIN_DIR}")
TOOL=$(readlink -f "${2:?}")
BIN=$(readlink -f "${3:?}")
HERE=$(cd "$(dirname "$0")" && pwd)
CC=${CC:-cc}
T=$(mktemp -d "${TMPDIR:-/tmp}/ts_export_c.XXXXXX")
trap 'rm -rf "$T"' EXIT
failures=0 checks=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { checks=$((checks + 1)); }

start=$(date +%s)
# The figures and their programs, as the figures_render fixture wrote them
# (make_figures --backend osmesa --out FIRST_RUN --export-c), copied here.
if ! ls "$FIRST"/*.c >/dev/null 2>&1; then
  fail "no exported programs in $FIRST (the figures_render fixture)"
  echo "export_c: $checks checks passed, $failures failed"
  exit 1
fi
cp "$FIRST"/*.png "$FIRST"/*.c "$FIRST"/*.texels "$T"/ 2>/dev/null

# Both builds and the offscreen run of one figure; prints "ID STATUS DETAIL".
build_one() {
  local id=$1
  cd "$T" || exit 1
  if ! $CC -std=c99 -Wall -Werror "$id.c" -o "$id.window" -lglfw -lGL -lm 2>"$id.window.log"; then
    echo "$id window-build $(head -c 300 "$id.window.log" | tr '\n' ' ')"; return; fi
  if ! $CC -std=c99 -Wall -Werror -DOFFSCREEN "$id.c" -o "$id.off" -lOSMesa -lm 2>"$id.off.log"; then
    echo "$id offscreen-build $(head -c 300 "$id.off.log" | tr '\n' ' ')"; return; fi
  if ! ./"$id.off" "$id.ppm" 2>"$id.run.log"; then echo "$id run $(head -c 300 "$id.run.log" | tr '\n' ' ')"; return; fi
  echo "$id ok $("$TOOL" diff-rgb "$T/$id.png" "$T/$id.ppm" 2>&1)"
}
export -f build_one
export T CC TOOL
ls "$T"/*.c | xargs -n1 basename | sed 's/\.c$//' | xargs -P2 -I{} bash -c 'build_one {}' >"$T/results" 2>&1

declare -A maxpx maxdiff
while read -r name px diff _; do
  case "$name" in ''|\#*) continue ;; esac
  maxpx[$name]=$px maxdiff[$name]=$diff
done < <(bash "$HERE/../../scripts/facts.sh" export_bound || echo "FAILED 0 0")
[ -z "${maxpx[FAILED]:-}" ] || fail "scripts/facts.sh export_bound: the demos' facts files do not read"
n=0
while read -r id status a b; do
  n=$((n + 1))
  if [ "$status" != ok ]; then fail "$id: $status failed: $a $b"; continue; fi
  pass; pass  # both builds
  px=${a:-x} diff=${b:-x}
  if ! [[ "$px" =~ ^[0-9]+$ && "$diff" =~ ^[0-9]+$ ]]; then fail "$id: cannot compare: $a $b"; continue; fi
  if [ "$px" -gt "${maxpx[$id]:-0}" ] || [ "$diff" -gt "${maxdiff[$id]:-0}" ]; then
    fail "$id: the exported program's picture differs from the demo's in $px pixels by up to $diff (bound ${maxpx[$id]:-0} / ${maxdiff[$id]:-0})"
  else
    pass
    echo "  $id: $px pixels differ, by up to $diff"
  fi
done <"$T/results"
figures=$(ls "$T"/*.png | wc -l)
[ "$n" -eq "$figures" ] && [ "$n" -gt 0 ] && pass || fail "$n programs for $figures figures"

# A state that cannot be exported: one line, exit 2, no file.
mkdir -p "$T/live"
( cd "$T/live" && "$BIN/parallax_aniso" --backend osmesa --view live --res 64 --size 160x120 --export-c live.c \
    >out 2>err ); rc=$?
if [ "$rc" -ne 2 ]; then fail "parallax_aniso --view live --export-c: exit $rc, want 2 ($(cat "$T/live/err"))"
elif [ "$(wc -l <"$T/live/err")" -ne 1 ]; then fail "live view: want one stderr line, got: $(cat "$T/live/err")"
elif ls "$T/live" | grep -q 'live\.'; then fail "live view: files written: $(ls "$T/live")"
else pass; fi

echo "export_c: $n figures exported, built twice and compared; $checks checks passed, $failures failed ($(( $(date +%s) - start )) s)"
[ "$failures" -eq 0 ]
