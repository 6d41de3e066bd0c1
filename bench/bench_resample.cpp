// Resampling throughput: splinefig's two-pass resampler against OpenImageIO's
// ImageBufAlgo::resize on the same float RGB images, one thread and all threads.
//   resample/up/<filter>/<impl>    2048x2048 -> 4096x4096
//   resample/down/<filter>/<impl>  2048x2048 -> 512x512
//   resample/up/memcpy-floor       copying a 4096x4096 RGB float buffer (reads and writes it)
//   resample/up/memset-floor       writing it once (the least any upsize must do)
// Outputs are allocated once and reused by every impl. The oiio rows carry the largest
// difference from splinefig's result as a counter (the accuracy behind the speed).
#include <benchmark/benchmark.h>

#include <splinefig/base/parallel.hpp>
#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <string>

using namespace splinefig;

namespace {

constexpr int kSource = 2048, kUp = 4096, kDown = 512;

const Image& source() {
  static const Image img = [] {
    Image s(kSource, kSource, 3);
    std::mt19937 rng(42);
    std::uniform_real_distribution<float> noise(-0.05f, 0.05f);
    for (int y = 0; y < kSource; ++y)
      for (int x = 0; x < kSource; ++x)
        for (int c = 0; c < 3; ++c)
          s.at(x, y, c) = 0.5f + 0.4f * std::sin(0.01f * float(x * (c + 1)) + 0.013f * float(y)) + noise(rng);
    return s;
  }();
  return img;
}

// Allocated and touched once, so that no impl pays for the first page faults.
Image& output(int size) {
  static Image up(kUp, kUp, 3), down(kDown, kDown, 3);
  static const bool touched = [] {
    std::memset(up.pixels.data(), 0, up.pixels.size() * sizeof(float));
    std::memset(down.pixels.data(), 0, down.pixels.size() * sizeof(float));
    return true;
  }();
  (void)touched;
  return size == kUp ? up : down;
}

int all_threads() { return worker_count(0); }

void splinefig_resample(benchmark::State& state, int size, const std::string& filter, int threads) {
  const Kernel f = parse_kernel(filter);
  ResampleOptions opt;
  opt.threads = threads;
  const Image& src = source();
  Image& dst = output(size);
  for (auto _ : state) {
    resample_into(src, dst, f, opt);
    benchmark::DoNotOptimize(dst.pixels.data());
    benchmark::ClobberMemory();
  }
  state.counters["threads"] = threads;
  state.SetItemsProcessed(state.iterations() * int64_t(size) * size);
}

void oiio_resize(benchmark::State& state, int size, const std::string& filter, int threads) {
  const Image& s = source();
  OIIO::ImageBuf src(OIIO::ImageSpec(s.width, s.height, 3, OIIO::TypeDesc::FLOAT), const_cast<float*>(s.pixels.data()));
  Image& out = output(size);
  OIIO::ImageBuf dst(OIIO::ImageSpec(size, size, 3, OIIO::TypeDesc::FLOAT), out.pixels.data());
  const std::string name = filter == "bspline" ? "bspline" : filter;
  for (auto _ : state) {
    if (!OIIO::ImageBufAlgo::resize(dst, src, name, 0.0f, {}, threads)) state.SkipWithError("resize failed");
    benchmark::ClobberMemory();
  }
  // Accuracy: the largest difference from splinefig's result (clamped edges, symmetric kernel).
  Image ours(size, size, 3);
  ResampleOptions opt;
  resample_into(s, ours, parse_kernel(filter), opt);
  double diff = 0;
  for (size_t i = 0; i < ours.pixels.size(); ++i) diff = std::max(diff, double(std::abs(ours.pixels[i] - out.pixels[i])));
  state.counters["max_abs_diff"] = diff;
  state.counters["threads"] = threads;
  state.SetItemsProcessed(state.iterations() * int64_t(size) * size);
}

void floor_memcpy(benchmark::State& state) {
  Image& dst = output(kUp);
  static const std::vector<float> from(dst.pixels.size(), 0.25f);
  for (auto _ : state) {
    std::memcpy(dst.pixels.data(), from.data(), from.size() * sizeof(float));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * int64_t(kUp) * kUp);
}

void floor_memset(benchmark::State& state) {
  Image& dst = output(kUp);
  for (auto _ : state) {
    std::memset(dst.pixels.data(), 0, dst.pixels.size() * sizeof(float));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * int64_t(kUp) * kUp);
}

const bool registered = [] {
  for (const char* dir : {"up", "down"}) {
    const int size = std::string(dir) == "up" ? kUp : kDown;
    for (const std::string filter : {"catmull-rom", "bspline"}) {
      const std::string base = std::string("resample/") + dir + "/" + filter + "/";
      benchmark::RegisterBenchmark((base + "splinefig-1t").c_str(), splinefig_resample, size, filter, 1)
          ->Unit(benchmark::kMillisecond)->UseRealTime();
      benchmark::RegisterBenchmark((base + "splinefig-mt").c_str(), splinefig_resample, size, filter, all_threads())
          ->Unit(benchmark::kMillisecond)->UseRealTime();
      benchmark::RegisterBenchmark((base + "oiio-1t").c_str(), oiio_resize, size, filter, 1)
          ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(std::string(dir) == "up" ? 2 : 4);
      benchmark::RegisterBenchmark((base + "oiio-mt").c_str(), oiio_resize, size, filter, all_threads())
          ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(std::string(dir) == "up" ? 2 : 4);
    }
    if (size == kUp) {
      benchmark::RegisterBenchmark("resample/up/memcpy-floor", floor_memcpy)->Unit(benchmark::kMillisecond)->UseRealTime();
      benchmark::RegisterBenchmark("resample/up/memset-floor", floor_memset)->Unit(benchmark::kMillisecond)->UseRealTime();
    }
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
