#!/usr/bin/env bash
# The test commands (CI runs both, one after the other: .ci/run).
#
#   bash scripts/test.sh          the quick level, minutes: set up, build, run
#                                 every test on llvmpipe through OSMesa, then
#                                 the GL tests on Mesa's second rasterizer
#                                 (softpipe) and on the EGL surfaceless backend.
#   bash scripts/test.sh --full   the full stages: the benchmark programs compiled
#                                 (not run: scripts/bench.sh runs them), the whole suite built with
#                                 AddressSanitizer + UndefinedBehaviorSanitizer
#                                 (build-asan/; the Xvfb window tests in a
#                                 second step with leak checking off: GLX's
#                                 libraries leak from code LeakSanitizer cannot
#                                 name once unloaded), then each libFuzzer
#                                 target for what is left of the budget.
#
# Each stage prints its duration and the load average it ran under; a summary
# follows.  Fuzzing gets what remains of TS_CI_BUDGET_SECONDS (default 2700:
# CI's 45 minutes, counted from TS_CI_START, the epoch second .ci/run started,
# or from this script's start) after a reserve for the fuzz build, split
# between the targets, 60..900 s each; TS_FUZZ_SECONDS=N fixes it instead.
# Extra arguments go to ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
level=quick
if [ "${1:-}" = --full ]; then level=full; shift; fi

start=$(date +%s)
: "${TS_CI_START:=$start}"
summary=""
stage() {  # stage NAME COMMAND...: runs it, prints and remembers its duration
  local name=$1 t0 t1 rc=0
  shift
  echo "== $name =="
  t0=$(date +%s)
  "$@" || rc=$?
  t1=$(date +%s)
  local line
  line=$(printf '%-44s %5d s   (load average %s)' "$name" $((t1 - t0)) "$(cut -d' ' -f1-3 /proc/loadavg)")
  if [ "$rc" -ne 0 ]; then line+="   FAILED (status $rc)"; fi
  echo "-- $line"
  summary+="$line"$'\n'
  if [ "$rc" -ne 0 ]; then
    printf '\nstage durations (%s level):\n%s' "$level" "$summary"
    exit "$rc"
  fi
}

stage "set-up (Debian packages)" bash scripts/setup.sh
if [ "$level" = quick ]; then
  stage "configure + build (build/)" bash -c 'cmake --preset default >/dev/null && cmake --build --preset default'
  stage "default suite (llvmpipe, OSMesa)" ctest --preset default "$@"
  stage "GL tests on softpipe" ctest --preset softpipe "$@"
  stage "GL tests on the EGL backend" ctest --preset egl "$@"
else
  # The quick level builds what its tests run; the benchmark programs are
  # compiled here (into build/, reusing its objects), so they cannot rot.
  stage "compile the benchmarks (build/, not run)" bash -c 'cmake --preset default -DTM_BUILD_BENCHMARKS=ON >/dev/null &&
    cmake --build --preset default --target bench_figures bench_window bench_jitter bench_parallax'
  stage "configure + build under ASan + UBSan" bash -c 'cmake --preset asan >/dev/null && cmake --build --preset asan'
  stage "the suite under ASan + UBSan" ctest --preset asan "$@"
  stage "window tests under ASan + UBSan" ctest --preset asan-window "$@"
  targets=$(ls fuzz/fuzz_*.cpp | wc -l)
  if [ -n "${TS_FUZZ_SECONDS:-}" ]; then
    each=$TS_FUZZ_SECONDS
  else
    # Reserve 300 s for the fuzz build (about 1 min quiet) and the margin.
    left=$(( ${TS_CI_BUDGET_SECONDS:-2700} - ($(date +%s) - TS_CI_START) - 300 ))
    each=$(( left / targets ))
    [ "$each" -lt 60 ] && each=60
    [ "$each" -gt 900 ] && each=900
  fi
  stage "fuzzing: $targets targets, $each s each" bash fuzz/run.sh "$each"
fi
printf '\nstage durations (%s level, %d s in all):\n%s' "$level" $(( $(date +%s) - start )) "$summary"
