#!/usr/bin/env bash
# fuzz/run.sh [SECONDS] — builds the libFuzzer targets (preset `fuzz`: clang,
# ASan + UBSan) and runs each for SECONDS (default 60).
#
# The corpus accumulates: each target starts from fuzz/corpus/<target>/ (kept
# in the repository: only inputs that raised coverage), the committed seeds
# (the reliability corpus, the book figures' sidecars) and what earlier runs
# on this machine found (build-fuzz/corpus/), after replaying every regression
# file.  At the end, inputs that raise coverage beyond fuzz/corpus/ are merged
# into it (libFuzzer's -merge=1): commit them, and the next run, on any
# machine, starts where this one stopped.
#
# A crash leaves its input in build-fuzz/artifacts/ and fails the run: add the
# file to tests/reliability/corpus/regressions/ (images) or
# fuzz/regressions/<target>/, fix the bug, and commit both.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH=${1:-60}
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
B=build-fuzz
export ASAN_OPTIONS=detect_leaks=1
export LSAN_OPTIONS=suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

# Each target and its seeds (a target whose program is not built is skipped, and said so).
targets=(png bmp sidecar jpeg)
seeds_for() {
  case "$1" in
    png) ls tests/reliability/corpus/*.png 2>/dev/null ;;
    bmp) ls tests/reliability/corpus/*.bmp 2>/dev/null ;;
    jpeg) ls tests/reliability/corpus/*.jpg tests/reliability/corpus/*.jpeg 2>/dev/null ;;
    sidecar) find book_figures -name "*.json" -size -64k | sort; ls fuzz/seeds/sidecar/* 2>/dev/null ;;
  esac
  true
}

status=0
report=""
for t in "${targets[@]}"; do
  bin="$B/bin/fuzz_$t"
  [ -x "$bin" ] || { report+="fuzz_$t: not built (no fuzz/fuzz_$t.cpp in this checkout)"$'\n'; continue; }
  kept=fuzz/corpus/$t work=$B/corpus/$t
  mkdir -p "$kept" "$work" "$B/artifacts"
  # 1. Regressions, seeds and the kept corpus, once each (must not crash).
  # (files only: given one folder, libFuzzer takes every argument for a folder)
  mapfile -t files < <(seeds_for "$t"; ls tests/reliability/corpus/regressions/* fuzz/regressions/"$t"/* 2>/dev/null || true)
  existing=()
  for f in "${files[@]}" "$kept"/*; do [ -f "$f" ] && existing+=("$f"); done
  if ! "$bin" -runs=0 "${existing[@]}" >"$B/fuzz_$t.replay.log" 2>&1; then
    echo "fuzz_$t: a seed, regression or kept input fails:"
    tail -30 "$B/fuzz_$t.replay.log"
    status=1
    continue
  fi
  for f in "${files[@]}"; do [ -f "$f" ] && cp -n "$f" "$work/" 2>/dev/null; done; true
  before=$(ls "$kept" | wc -l)
  # 2. SECONDS_EACH of fuzzing, from the kept corpus and the working one.
  echo "== fuzz_$t for ${SECONDS_EACH} s (from $before kept inputs) =="
  if "$bin" -max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2560 -malloc_limit_mb=2048 \
       -max_len=65536 -print_final_stats=1 -artifact_prefix="$B/artifacts/fuzz_$t-" "$work" "$kept" \
       >"$B/fuzz_$t.log" 2>&1; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$B/fuzz_$t.log")
    cov=$(grep -o 'cov: [0-9]*' "$B/fuzz_$t.log" | tail -1 | cut -d' ' -f2)
    # 3. Keep what raised coverage, cut to 8 KiB, so the committed corpus stays
    #    small (the large seeds are replayed from where they live anyway).
    "$bin" -merge=1 -max_len=8192 "$kept" "$work" >"$B/fuzz_$t.merge.log" 2>&1 || true
    after=$(ls "$kept" | wc -l)
    report+="fuzz_$t: ${runs:-?} executions in ${SECONDS_EACH} s ($(( ${runs:-0} / (SECONDS_EACH > 0 ? SECONDS_EACH : 1) )) per s), coverage ${cov:-?} edges, no crash; kept corpus $before -> $after inputs"$'\n'
  else
    echo "fuzz_$t FOUND A CRASH (input saved in $B/artifacts/):"
    grep -E "ERROR|SUMMARY|Test unit written|==[0-9]+==" "$B/fuzz_$t.log" | head -20
    status=1
  fi
done
printf '%s' "$report"
exit $status
