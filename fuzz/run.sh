#!/usr/bin/env bash
# fuzz/run.sh [SECONDS] — builds the libFuzzer targets (preset `fuzz`: clang,
# ASan + UBSan) and runs each for SECONDS (default 60), as many targets at a
# time as there are cores (FUZZ_PARALLEL=N to change it), each on its own
# core: on a 2-core machine the 4 targets take about 2 x SECONDS of wall
# time, plus the build and a few seconds of replays and merges.
#
# The corpus accumulates: each target starts from fuzz/corpus/<target>/ (kept
# in the repository: only inputs that raised coverage), the committed seeds
# (the reliability corpus; for the sidecar reader fuzz/seeds/sidecar/, small
# versions of the book figures' sidecars made by fuzz/seeds/make_sidecar_seeds.py)
# and what earlier runs on this machine found (build-fuzz/corpus/), after
# replaying every regression file, seed and kept input once.  At the end,
# inputs that raise coverage beyond fuzz/corpus/ are merged into it
# (libFuzzer's -merge=1): commit them, and the next run, on any machine,
# starts where this one stopped.
#
# Each target has a max_len suited to its format (max_len_for below): inputs
# longer than the decoder needs add nothing but time.  The seeds all fit.
#
# A crash leaves its input in build-fuzz/artifacts/ and fails the run: add the
# file to tests/reliability/corpus/regressions/ (images) or
# fuzz/regressions/<target>/, fix the bug, and commit both.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH=${1:-60}
PARALLEL=${FUZZ_PARALLEL:-$(nproc)}
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
B=build-fuzz
export ASAN_OPTIONS=detect_leaks=1
export LSAN_OPTIONS=suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

# Each target, its longest input, its seeds (copied into the working corpus)
# and what is replayed once before fuzzing (a target whose program is not
# built is skipped, and said so).
targets=(png bmp sidecar jpeg)
max_len_for() {
  # The images: the largest seed is 6.8 KiB (a 37x23 RGBA16 PNG; BMP 6.4,
  # JPEG 2.1).  The sidecar: the seeds are 0.2 to 3.5 KiB; 4 KiB runs 20 %
  # faster than 8 KiB for the same coverage (the JSON parse is most of the
  # time, and grows with the input).
  case "$1" in
    sidecar) echo 4096 ;;
    *) echo 8192 ;;
  esac
}
seeds_for() {
  case "$1" in
    png) ls tests/reliability/corpus/*.png 2>/dev/null ;;
    bmp) ls tests/reliability/corpus/*.bmp 2>/dev/null ;;
    jpeg) ls tests/reliability/corpus/*.jpg tests/reliability/corpus/*.jpeg 2>/dev/null ;;
    sidecar) ls fuzz/seeds/sidecar/* 2>/dev/null ;;
  esac
  true
}
replay_for() {
  seeds_for "$1"
  ls tests/reliability/corpus/regressions/* fuzz/regressions/"$1"/* 2>/dev/null || true
}
# The project's own files, read once each, whole, not fuzzed: the book
# figures' sidecars (< 64 KiB), their textures remade at full size
# (TS_FUZZ_WHOLE_TEXTURES=1: see fuzz/fuzz_sidecar.cpp).
real_files_for() {
  if [ "$1" = sidecar ]; then find book_figures -name "*.json" -size -64k | sort; fi
  true
}

# One target: replay, fuzz, merge.  Writes $B/fuzz_<t>.report (one line) and
# $B/fuzz_<t>.status (0 = fine); its output lines start with fuzz_<t>.
run_target() {
  local t=$1 bin="$B/bin/fuzz_$1" kept=fuzz/corpus/$1 work=$B/corpus/$1 maxlen
  maxlen=$(max_len_for "$t")
  mkdir -p "$kept" "$work" "$B/artifacts"
  # 1. Regressions, seeds, the kept corpus and the project's own files, once
  #    each (must not crash).
  # (files only: given one folder, libFuzzer takes every argument for a folder)
  local files existing=() f
  mapfile -t files < <(replay_for "$t")
  for f in "${files[@]}" "$kept"/*; do [ -f "$f" ] && existing+=("$f"); done
  mapfile -t files < <(real_files_for "$t")
  local real=()
  for f in "${files[@]}"; do [ -f "$f" ] && real+=("$f"); done
  if ! { "$bin" -runs=0 "${existing[@]}" &&
         { [ ${#real[@]} = 0 ] || TS_FUZZ_WHOLE_TEXTURES=1 "$bin" -runs=0 "${real[@]}"; }; } >"$B/fuzz_$t.replay.log" 2>&1; then
    echo "fuzz_$t: a seed, regression or kept input fails:"
    tail -30 "$B/fuzz_$t.replay.log" | sed "s/^/fuzz_$t: /"
    echo "fuzz_$t: FAILED in the replay (log: $B/fuzz_$t.replay.log)" >"$B/fuzz_$t.report"
    return 1
  fi
  mapfile -t files < <(seeds_for "$t")
  for f in "${files[@]}"; do [ -f "$f" ] && cp -n "$f" "$work/" 2>/dev/null; done
  # Inputs an earlier run kept here that are longer than max_len would only be cut.
  find "$work" -type f -size +"${maxlen}"c -delete
  local before after runs rate cov ft start=$SECONDS
  before=$(ls "$kept" | wc -l)
  # 2. SECONDS_EACH of fuzzing, from the working corpus and the kept one.
  echo "fuzz_$t: fuzzing for ${SECONDS_EACH} s, max_len $maxlen, from $before kept inputs and $(ls "$work" | wc -l) working ones"
  if ! "$bin" -max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2560 -malloc_limit_mb=2048 \
       -max_len="$maxlen" -print_final_stats=1 -artifact_prefix="$B/artifacts/fuzz_$t-" "$work" "$kept" \
       >"$B/fuzz_$t.log" 2>&1; then
    echo "fuzz_$t FOUND A CRASH (input saved in $B/artifacts/):"
    grep -E "ERROR|SUMMARY|Test unit written|==[0-9]+==" "$B/fuzz_$t.log" | head -20 | sed "s/^/fuzz_$t: /"
    echo "fuzz_$t: FOUND A CRASH (log: $B/fuzz_$t.log, input in $B/artifacts/)" >"$B/fuzz_$t.report"
    return 1
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$B/fuzz_$t.log")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$B/fuzz_$t.log")
  cov=$(grep -o 'cov: [0-9]*' "$B/fuzz_$t.log" | tail -1 | cut -d' ' -f2)
  ft=$(grep -o 'ft: [0-9]*' "$B/fuzz_$t.log" | tail -1 | cut -d' ' -f2)
  # 3. Keep what raised coverage (max_len long at most, so the committed
  #    corpus stays small; the large seeds are replayed from where they live).
  "$bin" -merge=1 -max_len="$maxlen" "$kept" "$work" >"$B/fuzz_$t.merge.log" 2>&1 || true
  after=$(ls "$kept" | wc -l)
  echo "fuzz_$t: ${runs:-?} executions in ${SECONDS_EACH} s (${rate:-?} per s), coverage ${cov:-?} edges (${ft:-?} features), no crash; kept corpus $before -> $after inputs ($(( SECONDS - start )) s with the merge)" \
    >"$B/fuzz_$t.report"
  cat "$B/fuzz_$t.report"
}

# PARALLEL at a time, each in its own process group, so that the trap can stop a
# fuzzer with the job that started it; nothing outlives the script.
# (Under set -m each background job is a process group whose id is the
# job's pid; only the jobs still running are stopped.)
set -m
stop_all() {
  local p
  for p in $(jobs -rp); do kill -TERM -- "-$p" 2>/dev/null || true; done
}
trap 'stop_all; exit 130' INT TERM
trap 'stop_all' EXIT

ran=()
for t in "${targets[@]}"; do
  bin="$B/bin/fuzz_$t"
  if [ ! -x "$bin" ]; then
    echo "fuzz_$t: not built (no fuzz/fuzz_$t.cpp in this checkout)" >"$B/fuzz_$t.report"
    rm -f "$B/fuzz_$t.status"
    ran+=("$t")
    continue
  fi
  while [ "$(jobs -rp | wc -l)" -ge "$PARALLEL" ]; do wait -n || true; done
  rm -f "$B/fuzz_$t.status" "$B/fuzz_$t.report"
  ( status=0; run_target "$t" || status=1; echo $status >"$B/fuzz_$t.status"; exit $status ) &
  ran+=("$t")
done
wait || true

status=0
echo
for t in "${ran[@]}"; do
  cat "$B/fuzz_$t.report" 2>/dev/null || echo "fuzz_$t: no report (stopped?)"
  if [ -x "$B/bin/fuzz_$t" ] && [ "$(cat "$B/fuzz_$t.status" 2>/dev/null)" != 0 ]; then status=1; fi
done
exit $status
