// bench_procedural — the cost of demos/procedural_texture's fractal terrain: a height field by recursive random
// midpoint displacement (diamond-square) built at depth 4..10, an edge of 2^d + 1 heights.  The work is one
// displacement a height, (2^d + 1)^2 of them: the time grows with the square of the edge's resolution (four times
// a level, where the edge doubles), faster than linearly.  Reported: time per field, heights, and heights a second
// (about constant if the cost is the heights').  Also the lattice noise's 64^3 solid texture at 1..6 octaves
// (linear in the octaves).  Speed is measured, never asserted.
#include <benchmark/benchmark.h>

#include <string>

#include "bench_common.hpp"
#include "demos/procedural_texture/procedural_texture_math.hpp"

namespace {
namespace pr = ts::proc;

void benchTerrain(benchmark::State& st, int depth) {
  double sink = 0;
  for (auto _ : st) {
    const pr::HeightField f = pr::diamondSquare(depth, 0.5, 7);
    sink += f.h[f.h.size() / 2];
  }
  benchmark::DoNotOptimize(sink);
  const double edge = double((1 << depth) + 1), heights = edge * edge;
  st.counters["edge"] = edge;
  st.counters["heights"] = heights;
  st.counters["heights_per_s"] = benchmark::Counter(heights * double(st.iterations()), benchmark::Counter::kIsRate);
}

// The octaves' sum at every texel centre of a 64^3 block (the solid texture's values, before the colour ramp).
void benchSolid(benchmark::State& st, int octaves) {
  const pr::Lattice& l = pr::lattice();
  constexpr int n = 64;
  double sink = 0;
  for (auto _ : st)
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) sink += pr::octaves(l, (i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n, octaves);
  benchmark::DoNotOptimize(sink);
  st.counters["texels"] = double(n) * n * n;
}
}  // namespace

int main(int argc, char** argv) {
  for (int depth = 4; depth <= 10; ++depth)
    benchmark::RegisterBenchmark(("terrain/depth/" + std::to_string(depth)).c_str(), benchTerrain, depth)
        ->Unit(benchmark::kMillisecond);
  for (int octaves = 1; octaves <= pr::kMaxOctaves; ++octaves)
    benchmark::RegisterBenchmark(("solid_noise/octaves/" + std::to_string(octaves)).c_str(), benchSolid, octaves)
        ->Unit(benchmark::kMillisecond);
  return ts::bench::run(argc, argv);
}
