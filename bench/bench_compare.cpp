// compare/idiff-metrics/<impl>: idiff's numbers (mean, RMS, PSNR, max error and its location,
// pixels over warn and fail) for two 2048 x 2048 RGBA float images in memory, one thread.
//   splinefig : compare::idiff_metrics(a, b, fail, warn, {.threads = 1})
//   oiio      : OpenImageIO's ImageBufAlgo::compare(A, B, fail, warn, roi, nthreads = 1)
//   splinefig-threads : the same with every hardware thread (not per core)
// items = pixels; the goal is >= 1 Gpixel/s per core. The argument is the side: 2048 streams
// 128 MiB per comparison from memory; 256 (0.5 MiB) stays in cache and shows the arithmetic.
#include <splinefig/compare/idiff.hpp>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>

namespace {

using splinefig::Image;

struct Pair {
  Image a, b;
  explicit Pair(int size) {
    a = Image::zeros(size, size, 4);
    b = a;
    std::uint32_t s = 1;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
      s = s * 1664525u + 1013904223u;
      a.pixels[i] = float(s >> 8) / float(1u << 24);
      b.pixels[i] = a.pixels[i] + ((s & 0xff) < 3 ? 0.01f : 0.0f);  // about 1% of values differ
    }
  }
};

const Pair& pair(int size) {
  static std::map<int, Pair> pairs;
  auto it = pairs.find(size);
  if (it == pairs.end()) it = pairs.emplace(size, Pair(size)).first;
  return it->second;
}

void splinefig_metrics(benchmark::State& state, int threads) {
  const int size = int(state.range(0));
  const Pair& p = pair(size);
  splinefig::compare::MetricOptions o;
  o.threads = threads;
  for (auto _ : state) {
    auto m = splinefig::compare::idiff_metrics(p.a, p.b, 1e-3f, 1e-4f, o);
    benchmark::DoNotOptimize(m);
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(size) * size);
}

void oiio_metrics(benchmark::State& state) {
  const int size = int(state.range(0));
  const Pair& p = pair(size);
  const OIIO::ImageSpec spec(size, size, 4, OIIO::TypeFloat);
  const OIIO::ImageBuf A(spec, const_cast<float*>(p.a.pixels.data()));
  const OIIO::ImageBuf B(spec, const_cast<float*>(p.b.pixels.data()));
  for (auto _ : state) {
    auto r = OIIO::ImageBufAlgo::compare(A, B, 1e-3f, 1e-4f, OIIO::ROI(), 1);
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(size) * size);
}

}  // namespace

BENCHMARK_CAPTURE(splinefig_metrics, one_thread, 1)->Name("compare/idiff-metrics/splinefig")->Arg(2048)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(oiio_metrics)->Name("compare/idiff-metrics/oiio")->Arg(2048)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(splinefig_metrics, all_threads, 0)->Name("compare/idiff-metrics/splinefig-threads")->Arg(2048)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
