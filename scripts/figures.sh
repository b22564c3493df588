#!/usr/bin/env bash
# The instructors' command: set up, build, and regenerate every book figure
# into book_figures/ (PNG + sidecar JSON + the gallery README.md), and the
# image assets the suite makes into textures/.
# Extra arguments go to make_figures, e.g. --scale 2 or --backend egl.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset default >/dev/null
cmake --build --preset default --target make_figures make_textures
./build/bin/make_textures textures >/dev/null
./build/bin/make_figures --out book_figures "$@"
