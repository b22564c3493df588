#!/usr/bin/env bash
# The test commands.  CI runs the first two, one after the other (.ci/run);
# the third is run by hand before a release (README, "Testing").
#
#   bash scripts/test.sh          the quick level, minutes: set up, build, run
#                                 every test on llvmpipe through OSMesa (the
#                                 window tests' smoke subset: each demo opens,
#                                 takes a key, saves with F12, shows its help
#                                 card and closes).
#   bash scripts/test.sh --full   the full stages: every other window case
#                                 (each key of each demo, the GL pane, resizes,
#                                 the mouse, never frozen), the GL tests again
#                                 on Mesa's second rasterizer (softpipe) and on
#                                 the EGL surfaceless backend, the benchmark
#                                 programs compiled (not run: scripts/bench.sh
#                                 runs them), the Windows build tested under
#                                 Wine (scripts/windows.sh --test),
#                                 then each libFuzzer target (the
#                                 decoders and the sidecar reader under ASan +
#                                 UBSan) for TS_FUZZ_SECONDS (default 60), two
#                                 at a time.
#   bash scripts/test.sh --asan   the sanitizer level, by hand: the suite
#                                 built with AddressSanitizer +
#                                 UndefinedBehaviorSanitizer (build-asan/: the
#                                 tests once each, the window smoke subset with
#                                 leak checking off: GLX's libraries leak from
#                                 code LeakSanitizer cannot name once
#                                 unloaded).  About 40 minutes on two cores:
#                                 with the other two levels it would not fit
#                                 CI's hour.
#   --under-load                  (before a level, or alone) runs the level
#                                 while two busy loops keep both cores loaded,
#                                 as a shared machine is; the loops end with
#                                 the run, however it ends.
#
# No test's verdict depends on how long anything takes; test timeouts are
# hang guards, 4x each test's quiet duration (tests/durations.tsv; a demo's own
# tests: its demos/<name>/facts.tsv).  Each stage prints its duration and the
# load average it ran under; a summary follows.  Extra arguments go to ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
level=quick load=0
while [ $# -gt 0 ]; do
  case "$1" in
    --full) level=full; shift ;;
    --asan) level=asan; shift ;;
    --under-load) load=1; shift ;;
    *) break ;;
  esac
done

if [ "$load" = 1 ]; then
  loops=()
  for _ in 1 2; do
    (trap 'exit 0' TERM; while :; do :; done) &
    loops+=($!)
  done
  trap 'kill "${loops[@]}" 2>/dev/null || true' EXIT INT TERM
  echo "== under load: two busy loops (pids ${loops[*]}) until this run ends =="
fi

start=$(date +%s)
summary=""
stage() {  # stage NAME COMMAND...: runs it, prints and remembers its duration
  local name=$1 t0 t1 rc=0 l0
  shift
  echo "== $name =="
  t0=$(date +%s)
  l0=$(cut -d' ' -f1 /proc/loadavg)
  "$@" || rc=$?
  t1=$(date +%s)
  local line
  # The load average (1 min) at the start and the end of the stage.
  line=$(printf '%-46s %5d s   (load average %s -> %s)' "$name" $((t1 - t0)) "$l0" "$(cut -d' ' -f1 /proc/loadavg)")
  if [ "$rc" -ne 0 ]; then line+="   FAILED (status $rc)"; fi
  echo "-- $line"
  summary+="$line"$'\n'
  if [ "$rc" -ne 0 ]; then
    printf '\nstage durations (%s level):\n%s' "$level" "$summary"
    exit "$rc"
  fi
}

stage "set-up (Debian packages)" bash scripts/setup.sh
if [ "$level" = asan ]; then
  stage "configure + build under ASan + UBSan" bash -c 'cmake --preset asan >/dev/null && cmake --build --preset asan'
  stage "the suite under ASan + UBSan" ctest --preset asan "$@"
  stage "window smoke tests under ASan + UBSan" ctest --preset asan-window "$@"
else
  # The release build; in the full level it is already there after the quick
  # level (CI), or built here.
  stage "configure + build (build/)" bash -c 'cmake --preset default >/dev/null && cmake --build --preset default'
fi
if [ "$level" = quick ]; then
  stage "quick suite (llvmpipe, OSMesa)" ctest --preset default "$@"
elif [ "$level" = full ]; then
  stage "window tests, every case (llvmpipe)" ctest --preset full "$@"
  stage "GL tests on softpipe" ctest --preset softpipe "$@"
  stage "GL tests on the EGL backend" ctest --preset egl "$@"
  # The benchmark programs are compiled (into build/, reusing its objects),
  # so they cannot rot.
  stage "compile the benchmarks (build/, not run)" bash -c 'cmake --preset default -DTS_BUILD_BENCHMARKS=ON >/dev/null &&
    cmake --build --preset default --target benchmarks'
  # The Windows build (MinGW-w64, its libraries cross-built from Debian's
  # sources) under Wine on Xvfb against this build: every figure and every
  # measurement in it, the command line's errors, one window per demo and the
  # exercise checker as a child process (tests/windows/wine_test.sh).
  stage "Windows build, tested under Wine" bash scripts/windows.sh --test
  targets=$(ls fuzz/fuzz_*.cpp | wc -l)
  each=${TS_FUZZ_SECONDS:-60}
  stage "fuzzing: $targets targets, $each s each" bash fuzz/run.sh "$each"
fi
printf '\nstage durations (%s level%s, %d s in all):\n%s' "$level" "$([ "$load" = 1 ] && echo ', under two busy loops')" \
  $(( $(date +%s) - start )) "$summary"
