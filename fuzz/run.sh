#!/usr/bin/env bash
# fuzz/run.sh [SECONDS] — builds the libFuzzer targets (preset `fuzz`: clang,
# ASan + UBSan) and runs each for SECONDS (default 60): fuzz_png, fuzz_bmp,
# fuzz_sidecar.  Each starts from the committed seeds (the reliability corpus,
# the book figures' sidecars) plus what earlier runs found (build-fuzz/corpus/),
# after replaying every regression file.  A crash leaves its input in
# build-fuzz/artifacts/ and fails the run: add the file to
# tests/reliability/corpus/regressions/ (images) or fuzz/regressions/sidecar/
# (JSON), fix the bug, and commit both.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH=${1:-60}
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
B=build-fuzz
mkdir -p "$B/artifacts" "$B/corpus/png" "$B/corpus/bmp" "$B/corpus/sidecar"
export ASAN_OPTIONS=detect_leaks=1
export LSAN_OPTIONS=suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

seeds_png=(tests/reliability/corpus/*.png)
seeds_bmp=(tests/reliability/corpus/*.bmp)
mapfile -t seeds_sidecar < <(find book_figures -name "*.json" -size -64k | sort; ls fuzz/seeds/sidecar/*)
status=0
report=""
for t in png bmp sidecar; do
  seeds="seeds_$t[@]"
  # 1. Regressions and seeds, once each (must not crash).
  regress=(tests/reliability/corpus/regressions/* fuzz/regressions/"$t"/*)
  files=()
  for f in "${!seeds}" "${regress[@]}"; do [ -f "$f" ] && files+=("$f"); done
  "$B/bin/fuzz_$t" -runs=0 "${files[@]}" >"$B/fuzz_$t.replay.log" 2>&1 ||
    { echo "fuzz_$t: a seed or regression file fails:"; tail -30 "$B/fuzz_$t.replay.log"; status=1; continue; }
  # 2. Seeds copied into the working corpus, then SECONDS_EACH of fuzzing.
  cp -n "${files[@]}" "$B/corpus/$t/" 2>/dev/null || true
  echo "== fuzz_$t for ${SECONDS_EACH} s =="
  if "$B/bin/fuzz_$t" -max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2560 -malloc_limit_mb=2048 \
       -max_len=65536 -print_final_stats=1 -artifact_prefix="$B/artifacts/fuzz_$t-" "$B/corpus/$t" \
       >"$B/fuzz_$t.log" 2>&1; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$B/fuzz_$t.log")
    report+="fuzz_$t: ${runs:-?} executions in ${SECONDS_EACH} s, no crash; corpus $(ls "$B/corpus/$t" | wc -l) files"$'\n'
  else
    echo "fuzz_$t FOUND A CRASH (input saved in $B/artifacts/):"
    grep -E "ERROR|SUMMARY|Test unit written|==[0-9]+==" "$B/fuzz_$t.log" | head -20
    status=1
  fi
done
printf '%s' "$report"
exit $status
