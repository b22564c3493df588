#!/usr/bin/env bash
# scripts/durations.sh — measures every CTest test's duration and prints the
# table tests/durations.tsv holds (each test's TIMEOUT is 4x its row): the
# slowest of the release presets (default, full, softpipe, egl) and, when build-asan/
# exists, the ASan + UBSan run (asan, asan-window).  Run it on a quiet machine
# (nothing else building or testing: `uptime` near 0 before it starts) after
# adding a test or a demo, and commit the table (it multiplies each time by 1.8):
#   bash scripts/durations.sh > tests/durations.tsv.new && mv tests/durations.tsv.new tests/durations.tsv
# A demo's own tests (fig_<stem> of demos/<name>/<stem>_test.cpp, window_full_<name>)
# are not in that table: their rows are printed on stderr, as the `duration`
# rows to put in each demo's demos/<name>/facts.tsv.
# It reads the builds as they are: build them first (scripts/test.sh does).
set -euo pipefail
cd "$(dirname "$0")/.."
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
run() {  # run NAME PRESET: one preset's log, "name seconds" per line
  ctest --preset "$2" >"$T/$1.log" 2>&1 || echo "note: preset $2 had failures (durations still recorded)" >&2
  sed -n 's/^.*Test *#[0-9]*: \([A-Za-z0-9_]*\) .*Passed *\([0-9.]*\) sec.*$/\1 \2/p' "$T/$1.log" >"$T/$1.txt"
}
for p in default full softpipe egl; do run "$p" "$p"; done
asan=0
if [ -d build-asan ]; then
  asan=1
  run asan asan
  run asan-window asan-window
fi
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
cat <<EOF
# Each CTest test's duration in seconds, from which its TIMEOUT is set
# (CMakeLists.txt, ts_apply_timeouts): 4x the release column for the release
# build, 4x the asan column for the ASan + UBSan build, at least 120 s.  A
# timeout only stops a hung test: no verdict depends on it.
# Written by scripts/durations.sh on $(date -u +%F), load average $load_before
# before and $load_after after: each column is the slowest preset the test ran
# in (release: default, full, softpipe, egl; asan: asan, asan-window), times
# 1.8, the spread in speed between hosts of this kind, so a healthy test on
# the slowest host, even under a two-loop load (measured about 2x), stays
# within its timeout.  A test not run under ASan has 5x its release time
# there.  A test missing here gets 600 s and a note at configure time.
# test	release_s	asan_s
EOF
cat "$T"/default.txt "$T"/full.txt "$T"/softpipe.txt "$T"/egl.txt | sort -k1,1 -k2,2gr | awk '!seen[$1]++' >"$T/release"
if [ "$asan" = 1 ]; then cat "$T"/asan.txt "$T"/asan-window.txt | sort -k1,1 -k2,2gr | awk '!seen[$1]++' >"$T/asan"
else : >"$T/asan"; fi
join -a1 -e - -o 0,1.2,2.2 "$T/release" "$T/asan" |
  awk '{ r = $2 * 1.8; printf "%s\t%.2f\t%.2f\n", $1, r, ($3 == "-" ? r * 5 : $3 * 1.8) }' >"$T/rows"
# The demo a test belongs to, if any: its figure test's folder, or its window test's demo.
demo_of() {
  local t=$1 f
  case "$t" in
    window_full_*) [ -f "demos/${t#window_full_}/${t#window_full_}.cpp" ] && echo "${t#window_full_}" ;;
    fig_*) for f in demos/*/"${t#fig_}"_test.cpp; do [ -f "$f" ] && basename "$(dirname "$f")"; done ;;
  esac
}
while IFS=$'\t' read -r test release asan_s; do
  demo=$(demo_of "$test")
  if [ -n "$demo" ]; then echo "demos/$demo/facts.tsv: duration  $test  $release  $asan_s" >&2
  else printf '%s\t%s\t%s\n' "$test" "$release" "$asan_s"; fi
done <"$T/rows"
