#!/usr/bin/env bash
# The benchmark command: set up, build the Google Benchmark programs in
# build-bench/, and run them: every registered figure's offscreen stages
# (context, measure, build, render, readback, PNG encode; OSMesa and EGL), then
# its frames per second in a 1024x768 window under Xvfb; each Figure VI.7
# sampling mode at 1024x768; each parallax filtering mode at 800x600; the filter
# zoo's exact reference at 800x600; lighting from an environment map against
# per-pixel Phong at 1, 4 and 16 lights, 768x768; the dynamic cube map's pass, all
# six faces against only the faces each reflector reads; animated-texture uploads;
# N textures against one atlas; the clipmap's update; the sources' cost
# claims (hyperbolic interpolation, relief as texture or geometry, texture
# switches, minification with and without mipmaps).  Speed is measured,
# not asserted: nothing here is a CTest test.
#
# Extra arguments go to every program, e.g.
#   scripts/bench.sh --benchmark_filter=vi1_quad_variants --benchmark_repetitions=9
# Each program ends with markdown tables of the medians (for the README);
# the full results are kept as JSON in build-bench/bench/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
build=build-bench
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DTS_BUILD_TESTS=ON -DTS_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" -j2 --target benchmarks
mkdir -p "$build/bench"
# Each offscreen program in turn (bench_figures first: the figures' stages), then the windows under Xvfb.
"$build/bin/bench_figures" --benchmark_out="$build/bench/figures.json" --benchmark_out_format=json "$@"
for prog in "$build"/bin/bench_*; do
  name=$(basename "$prog")
  case "$name" in bench_figures | bench_window) continue ;; esac
  "$prog" --benchmark_out="$build/bench/${name#bench_}.json" --benchmark_out_format=json "$@"
done
xvfb-run -a -s "-screen 0 1280x1024x24" \
  "$build/bin/bench_window" --benchmark_out="$build/bench/window.json" --benchmark_out_format=json "$@"
