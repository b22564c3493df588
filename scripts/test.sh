#!/usr/bin/env bash
# The test command (CI runs exactly this): set up, build, run every test on
# llvmpipe through OSMesa, then the GL tests again on Mesa's second rasterizer
# (softpipe) and on the EGL surfaceless backend; then the whole suite again
# built with AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/; the
# Xvfb window tests in a second step with leak checking off: GLX's libraries
# leak from code LeakSanitizer cannot name once they are unloaded), and
# each libFuzzer target for TS_FUZZ_SECONDS (default 60) seconds
# (build-fuzz/).  TS_SKIP_SANITIZERS=1 skips the last two (a quick local
# run).  Extra arguments go to ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset default >/dev/null
cmake --build --preset default
ctest --preset default "$@"
echo "== GL tests on softpipe =="
ctest --preset softpipe "$@"
echo "== GL tests on the EGL backend =="
ctest --preset egl "$@"
if [ "${TS_SKIP_SANITIZERS:-0}" != 1 ]; then
  echo "== the whole suite under ASan + UBSan (build-asan) =="
  cmake --preset asan >/dev/null
  cmake --build --preset asan
  ctest --preset asan "$@"
  echo "== the window tests under ASan + UBSan (leak checking off) =="
  ctest --preset asan-window "$@"
  echo "== fuzzing: each target for ${TS_FUZZ_SECONDS:-60} s (build-fuzz) =="
  bash fuzz/run.sh "${TS_FUZZ_SECONDS:-60}"
fi
