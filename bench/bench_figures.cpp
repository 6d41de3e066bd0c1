// Workload D: what users draw. Every built-in figure (figures/specs) at scale 4, measured
// inside the process: the specs are loaded before timing, and no file is written.
//   figures/D/<name>/layout      layout_figure(): spec -> display list (sampling, text setting)
//   figures/D/<name>/render      render_figure() on 1 thread: layout + rasterize
//   figures/D/<name>/render-mt   render_figure() on all threads (wall time)
//   figures/D/all/...            the same for all figures in a row
//   memory/D/render[-mt]         peak memory rendering all figures adds (counter added_MB,
//                                measured in a forked child, bench/peak_memory.hpp)
// Rasterize time = render - layout. Figures with image elements read their raster files when
// rendered (filter-* figures read none; this is the only file I/O in the timed part).
#include <peak_memory.hpp>

#include <splinefig/figures/catalog.hpp>
#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>

#include <benchmark/benchmark.h>

#include <cstdio>
#include <thread>
#include <vector>

namespace sf = splinefig::figures;

namespace {

constexpr double kScale = 4;

const std::vector<sf::FigureSpec>& specs() {
  static const std::vector<sf::FigureSpec> all = [] {
    std::vector<sf::FigureSpec> v;
    const std::string dir = sf::builtin_specs_dir();
    if (dir.empty()) return v;
    for (const sf::SpecFile& f : sf::list_specs(dir)) v.push_back(sf::load_spec(f.path));
    return v;
  }();
  return all;
}

// `which` < 0: all figures.
void BM_layout(benchmark::State& state, int which) {
  const auto& all = specs();
  for (auto _ : state)
    for (int i = 0; i < static_cast<int>(all.size()); ++i)
      if (which < 0 || i == which) {
        sf::FigureInfo info = sf::layout_figure(all[static_cast<std::size_t>(i)], kScale);
        benchmark::DoNotOptimize(info.axes.data());
      }
}

void BM_render(benchmark::State& state, int which, int threads) {
  const auto& all = specs();
  std::int64_t pixels = 0;
  for (auto _ : state)
    for (int i = 0; i < static_cast<int>(all.size()); ++i)
      if (which < 0 || i == which) {
        sf::RenderedFigure r = sf::render_figure(all[static_cast<std::size_t>(i)], {kScale, threads});
        benchmark::DoNotOptimize(r.image.pixels.data());
        pixels += static_cast<std::int64_t>(r.info.width) * r.info.height;
      }
  state.counters["Mpixel/s"] = benchmark::Counter(static_cast<double>(pixels) * 1e-6, benchmark::Counter::kIsRate);
}

void BM_memory(benchmark::State& state, int threads) {
  const auto& all = specs();
  double added = 0;
  for (auto _ : state)
    added = bench::peak_added_mb([] {}, [&] {
      for (const sf::FigureSpec& s : all) {
        sf::RenderedFigure r = sf::render_figure(s, {kScale, threads});
        benchmark::DoNotOptimize(r.image.pixels.data());
      }
    });
  state.counters["added_MB"] = added;
}

void register_all() {
  const int all = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const auto& v = specs();
  if (v.empty()) {
    std::fprintf(stderr, "bench_figures: no built-in specs found (set SPLINEFIG_SPECS_DIR)\n");
    return;
  }
  auto add = [&](const std::string& name, int which) {
    const std::string base = "figures/D/" + name + "/";
    benchmark::RegisterBenchmark((base + "layout").c_str(), BM_layout, which)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((base + "render").c_str(), BM_render, which, 1)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((base + "render-mt").c_str(), BM_render, which, all)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  };
  add("all", -1);
  for (std::size_t i = 0; i < v.size(); ++i) add(v[i].name, static_cast<int>(i));
  benchmark::RegisterBenchmark("memory/D/render", BM_memory, 1)->Iterations(1)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("memory/D/render-mt", BM_memory, all)->Iterations(1)->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
