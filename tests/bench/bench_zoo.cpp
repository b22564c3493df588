// bench_zoo — the filter zoo's exact reference ("Speed"): the
// area integral over every pixel's preimage of the slanted plane at 800 x 600
// must take at most 2 s on this machine, and its cost must grow with the
// footprint's texel count, not with the texture's size.  No GL.
//
//   zoo/exact_800x600/<azimuth>           ts::AreaIntegral (Green's theorem along the outline), one thread
//   zoo/exact_800x600_2threads/<azimuth>  the same, rows shared by two threads (the demo's way)
//   zoo/exact_far_field/{outline,clip}    the far field only (LOD 1.5..5), the outline integral against
//                                         clipping every texel (ts::exactAreaAverage): same numbers
//   zoo/exact_texture/<side>              the same 800 x 600 view with textures of side 256 .. 4096 (the same
//                                         texel density: the pieces do not change, and the time should not
//                                         much: the summary prints the 4096 / 256 ratio, 4.4 with row-major
//                                         tables, 2.3 with 64-byte records in 8 x 8 tiles, see the README for
//                                         today's 16-byte packed sums in column-major 16 x 16 tiles)
//   zoo/exact_footprint/<texels a pixel>  a flat 256 x 256 view at 1, 4, 16, 64 texels a pixel: the cost
//                                         per pixel grows with the footprint (its outline: linearly)
// Counters: pixels, pieces (the outline integral's edge pieces, its cost)
// per pixel.  Wall clock, medians of 5; the load average is printed.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <thread>

#include "bench_common.hpp"
#include "common/core/layout.hpp"
#include "demos/filter_zoo/filter_zoo_math.hpp"

namespace {
using namespace zoo;

const ts::Image& checker(int side) {
  static std::map<int, ts::Image> cache;
  auto it = cache.find(side);
  if (it == cache.end()) it = cache.emplace(side, *ts::checkerboard(side, side / 32).image).first;
  return it->second;
}

// Every covered pixel's exact average; returns the pieces summed.
long exactAll(const View& v, const ts::AreaIntegral& a, int first, int step, double* sink) {
  long pieces = 0;
  for (int row = first; row < v.h; row += step)
    for (int col = 0; col < v.w; ++col) {
      if (!v.coversPixel(col, row)) continue;
      long p = 0;
      *sink += a.average(v.preimage(col, row), &p).r;
      pieces += p;
    }
  return pieces;
}
long coveredPixels(const View& v) {
  long n = 0;
  for (int row = 0; row < v.h; ++row)
    for (int col = 0; col < v.w; ++col) n += v.coversPixel(col, row);
  return n;
}

void exact800(benchmark::State& st, double az, int threads) {
  const View v = slantView(800, 600, az);
  const ts::AreaIntegral a(checker(256));
  double sink = 0;
  long pieces = 0;
  for (auto _ : st) {
    if (threads == 1) {
      pieces = exactAll(v, a, 0, 1, &sink);
    } else {
      double other = 0;
      long p2 = 0;
      std::thread t([&] { p2 = exactAll(v, a, 1, 2, &other); });
      pieces = exactAll(v, a, 0, 2, &sink) + (t.join(), p2);
      sink += other;
    }
    benchmark::DoNotOptimize(sink);
  }
  const long px = coveredPixels(v);
  st.counters["pixels"] = double(px);
  st.counters["pieces_per_pixel"] = double(pieces) / double(px);
}

void farFieldOnly(benchmark::State& st, bool clip) {
  const View v = slantView(800, 600, 45);
  const std::vector<char> mask = zoo::farField(v, 1.5, 5.0);
  const ts::AreaIntegral a(checker(256));
  double sink = 0;
  long px = 0;
  for (auto _ : st) {
    px = 0;
    for (int row = 0; row < v.h; ++row)
      for (int col = 0; col < v.w; ++col) {
        if (!mask[size_t(row) * size_t(v.w) + size_t(col)]) continue;
        sink += clip ? ts::exactAreaAverage(checker(256), v.preimage(col, row)).r : a.average(v.preimage(col, row)).r;
        ++px;
      }
    benchmark::DoNotOptimize(sink);
  }
  st.counters["pixels"] = double(px);
}

void textureSize(benchmark::State& st, int side) {
  const View v = slantView(800, 600, 22.5);
  const ts::AreaIntegral a(checker(side));
  double sink = 0;
  long pieces = 0;
  for (auto _ : st) {
    pieces = exactAll(v, a, 0, 1, &sink);
    benchmark::DoNotOptimize(sink);
  }
  st.counters["pieces_per_pixel"] = double(pieces) / double(coveredPixels(v));
}

void footprintSize(benchmark::State& st, double texelsPerPixel) {
  const View v = flatView(256, 256, 30, texelsPerPixel, {128, 128});
  const ts::AreaIntegral a(checker(256));
  double sink = 0;
  long pieces = 0;
  for (auto _ : st) {
    pieces = exactAll(v, a, 0, 1, &sink);
    benchmark::DoNotOptimize(sink);
  }
  st.counters["pieces_per_pixel"] = double(pieces) / (256.0 * 256.0);
  st.counters["texels_per_pixel"] = texelsPerPixel * texelsPerPixel;
}
}  // namespace

int main(int argc, char** argv) {
  for (double az : {0.0, 22.5, 45.0}) {
    const std::string k = ts::layout::fmt("%g", az);
    benchmark::RegisterBenchmark(("zoo/exact_800x600/" + k).c_str(), exact800, az, 1)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    benchmark::RegisterBenchmark(("zoo/exact_800x600_2threads/" + k).c_str(), exact800, az, 2)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
  benchmark::RegisterBenchmark("zoo/exact_far_field/outline", farFieldOnly, false)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::RegisterBenchmark("zoo/exact_far_field/clip", farFieldOnly, true)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  for (int side : {256, 1024, 4096})
    benchmark::RegisterBenchmark(("zoo/exact_texture/" + std::to_string(side)).c_str(), textureSize, side)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  for (double k : {1.0, 4.0, 16.0, 64.0})
    benchmark::RegisterBenchmark(("zoo/exact_footprint/" + ts::layout::fmt("%g", k)).c_str(), footprintSize, k)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  return ts::bench::run(argc, argv, [](const ts::bench::SummaryReporter& rep) {
    std::printf("\n| the exact reference | ms (%s) |\n|---|---|\n", rep.statistic().c_str());
    for (const char* n :
         {"zoo/exact_800x600/0", "zoo/exact_800x600/22.5", "zoo/exact_800x600/45", "zoo/exact_800x600_2threads/0",
          "zoo/exact_800x600_2threads/22.5", "zoo/exact_800x600_2threads/45", "zoo/exact_far_field/outline",
          "zoo/exact_far_field/clip", "zoo/exact_texture/256", "zoo/exact_texture/1024", "zoo/exact_texture/4096",
          "zoo/exact_footprint/1", "zoo/exact_footprint/4", "zoo/exact_footprint/16", "zoo/exact_footprint/64"})
      std::printf("| `%s` | %s |\n", n, ts::bench::fmt(rep.ms(n)).c_str());
    const double t256 = rep.ms("zoo/exact_texture/256"), t4096 = rep.ms("zoo/exact_texture/4096");
    if (t256 > 0 && t4096 > 0)
      std::printf("\nThe exact reference's time, texture 4096^2 / 256^2 (same view, same footprints): %.2f\n",
                  t4096 / t256);
  });
}
