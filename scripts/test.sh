#!/usr/bin/env bash
# The test command (CI runs exactly this): set up, build, run every test on
# llvmpipe through OSMesa, then the GL tests again on Mesa's second rasterizer
# (softpipe) and on the EGL surfaceless backend.  Extra arguments go to ctest.
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
