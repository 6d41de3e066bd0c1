// Stroke rasterization: splinefig (one thread and all cores) against Cairo, AGG and Blend2D on
// the stroke workloads A, B and C, 1024x1024, opaque black on white, canvas cleared every
// iteration. Blend2D is a peer when the bench is configured with -DSPLINEFIG_BLEND2D_SOURCE_DIR
// (bench/CMakeLists.txt); otherwise its rows are reported as absent (skipped, no number). Its
// context renders synchronously on the calling thread (thread_count 0) and is ended (flushed)
// inside the timed loop.
//   A1, A3: 100,000 separate segments (each its own path, butt caps), width 1 and 3.
//   B:      one open polyline of 1,000,000 points (a 3:4 Lissajous), width 1.5, round joins.
//   C:      10,000 random walks of 100 points, width 2, miter joins (limit 4).
//   R:      one random self-crossing polyline, width 1, butt caps, miter joins: points uniform
//           on the canvas (R1k, R10k, R30k, R100k, R1M: 10^3 to 10^6 points; the crossings grow
//           as n^2), or a random walk with normal steps (sigma 8) reflected into the canvas (Rw100k,
//           Rw1M: 10^5 and 10^6 points).
// stroke/<A1|A3|B|C>/rasterize and rasterize-mt time rasterize alone, on one thread and on all
// cores, the scene recorded before the timing.
// After the runs it prints the ratio table: splinefig's one-thread CPU time against Cairo's,
// AGG's and Blend2D's, and its wall-time speed-up on all threads (the whole drawing, and
// rasterize alone), each marked where it misses its goal.
// accuracy/<set>/<impl> renders random strokes (set "random") or seeded walks of hairpins,
// near-reversals and sub-width segments (set "walks") and reports the coverage error against the
// exact union oracle of the tests (counters max_err, mean_err); it is measured once, not timed.
// accuracy/dense/<workload> does the same for the dense workloads at the default coverage
// tolerance, in two windows of each, and says how many bands were drawn from the pieces.
// memory/<workload>/<impl> reports the peak memory drawing adds to a process (counter
// added_MB, measured in a forked child, bench/peak_memory.hpp) and what its input takes
// (input_MB); splinefig on one thread and on all threads, copying the points into its scene,
// and on one thread handing them over (splinefig-moved: Scene::stroke_polyline(vector&&)).
#include <oracle/sharp_walks.hpp>
#include <oracle/union_coverage.hpp>
#include <peak_memory.hpp>

#include <splinefig/renderer/renderer.hpp>

#include <agg_conv_stroke.h>
#include <agg_path_storage.h>
#include <agg_pixfmt_rgba.h>
#include <agg_rasterizer_scanline_aa.h>
#include <agg_renderer_base.h>
#include <agg_renderer_scanline.h>
#include <agg_rendering_buffer.h>
#include <agg_scanline_u.h>
#include <benchmark/benchmark.h>
#include <unistd.h>
#include <cairo.h>
#ifdef SPLINEFIG_HAVE_BLEND2D
#include <blend2d/blend2d.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <string>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <random>
#include <thread>
#include <tuple>
#include <vector>

namespace sr = splinefig::render;

namespace {

constexpr int kSize = 1024;

double frac(double v) { return v - std::floor(v); }

double h01(std::uint64_t x) {  // splitmix64 finalizer -> [0, 1)
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return static_cast<double>(x >> 11) / 9007199254740992.0;
}

struct Path {
  std::vector<sr::Vec2> pts;
};

struct Workload {
  std::vector<Path> paths;
  double width;
  sr::Join join;
  sr::Cap cap = sr::Cap::Butt;
};

Workload segments(double width) {
  Workload w{{}, width, sr::Join::Miter};
  w.paths.reserve(100000);
  for (int i = 0; i < 100000; ++i) {
    double x0 = kSize * frac(0.6180339887498949 * i), y0 = kSize * frac(0.7548776662466927 * i);
    double a = 2 * std::numbers::pi * frac(0.5698402909980532 * i), len = 5 + 45 * frac(0.3247179572447460 * i);
    w.paths.push_back({{{x0, y0}, {x0 + len * std::cos(a), y0 + len * std::sin(a)}}});
  }
  return w;
}

Workload lissajous() {
  Workload w{{}, 1.5, sr::Join::Round};
  Path p;
  p.pts.resize(1000000);
  for (int k = 0; k < 1000000; ++k) {
    double t = 2 * std::numbers::pi * k / 999999.0;
    p.pts[static_cast<std::size_t>(k)] = {512 + 480 * std::sin(3 * t + std::numbers::pi / 2), 512 + 480 * std::sin(4 * t)};
  }
  w.paths.push_back(std::move(p));
  return w;
}

Workload walks() {
  Workload w{{}, 2.0, sr::Join::Miter};
  w.paths.reserve(10000);
  for (int p = 0; p < 10000; ++p) {
    Path path;
    sr::Vec2 q{kSize * frac(0.6180339887498949 * p), kSize * frac(0.7548776662466927 * p)};
    path.pts.push_back(q);
    for (int j = 1; j < 100; ++j) {
      double a = 2 * std::numbers::pi * h01(static_cast<std::uint64_t>(100 * p + j));
      q = {q.x + 3 * std::cos(a), q.y + 3 * std::sin(a)};
      path.pts.push_back(q);
    }
    w.paths.push_back(std::move(path));
  }
  return w;
}

Workload uniform_polyline(int n) {
  Workload w{{}, 1.0, sr::Join::Miter};
  Path p;
  for (int k = 0; k < n; ++k)
    p.pts.push_back({kSize * h01(2 * static_cast<std::uint64_t>(k)), kSize * h01(2 * static_cast<std::uint64_t>(k) + 1)});
  w.paths.push_back(std::move(p));
  return w;
}

Workload walk_polyline(int n) {
  Workload w{{}, 1.0, sr::Join::Miter};
  std::mt19937_64 rng(20261202);
  std::normal_distribution<double> step(0, 8);
  auto reflect = [](double v) {
    v = std::fmod(v, 2.0 * kSize);
    if (v < 0) v += 2.0 * kSize;
    return v > kSize ? 2.0 * kSize - v : v;
  };
  Path p;
  sr::Vec2 q{kSize / 2.0, kSize / 2.0};
  for (int k = 0; k < n; ++k) {
    p.pts.push_back(q);
    q = {reflect(q.x + step(rng)), reflect(q.y + step(rng))};
  }
  w.paths.push_back(std::move(p));
  return w;
}

Workload make_workload(char id) {
  switch (id) {
    case '1': return segments(1);
    case '3': return segments(3);
    case 'B': return lissajous();
    case 'u': return uniform_polyline(1000);
    case 'v': return uniform_polyline(10000);
    case 'x': return uniform_polyline(30000);
    case 'y': return uniform_polyline(100000);
    case 'z': return uniform_polyline(1000000);
    case 'w': return walk_polyline(100000);
    case 'W': return walk_polyline(1000000);
    default: return walks();
  }
}

const Workload& workload(char id) {
  static std::map<char, Workload> made;
  auto it = made.find(id);
  if (it == made.end()) it = made.emplace(id, make_workload(id)).first;
  return it->second;
}

// ---- splinefig -------------------------------------------------------------------------
sr::Scene splinefig_scene(const Workload& w, int size, sr::Color bg, sr::Color ink, double tolerance) {
  sr::Scene s(size, size, bg);
  s.set_max_crossings(INFINITY);  // R30k crosses about 4e8 times, past the default work limit
  s.set_coverage_tolerance(tolerance);
  sr::StrokeStyle st;
  st.width = w.width;
  st.join = w.join;
  st.cap = w.cap;
  st.miter_limit = 4;
  for (const Path& p : w.paths) s.stroke_polyline(p.pts, false, st, ink);
  return s;
}

splinefig::Image draw_splinefig(const Workload& w, int threads, int size = kSize, sr::Color bg = {1, 1, 1, 1},
                         sr::Color ink = {0, 0, 0, 1}, double tolerance = sr::kDefaultCoverageTolerance,
                         sr::RasterReport* report = nullptr) {
  const sr::Scene s = splinefig_scene(w, size, bg, ink, tolerance);
  return sr::rasterize(s, threads, report);
}

// The same, handing the points over to the scene (the rvalue overload) instead of copying them.
splinefig::Image draw_splinefig_moved(Workload&& w, int threads) {
  sr::Scene s(kSize, kSize, {1, 1, 1, 1});
  s.set_max_crossings(INFINITY);
  sr::StrokeStyle st;
  st.width = w.width;
  st.join = w.join;
  st.cap = w.cap;
  st.miter_limit = 4;
  for (Path& p : w.paths) s.stroke_polyline(std::move(p.pts), false, st, {0, 0, 0, 1});
  w.paths = {};
  return sr::rasterize(s, threads);
}

// ---- Cairo -----------------------------------------------------------------------------
struct CairoCanvas {
  cairo_surface_t* surface;
  cairo_t* cr;
  explicit CairoCanvas(int size = kSize) {
    surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, size, size);
    cr = cairo_create(surface);
  }
  ~CairoCanvas() {
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
  }
};

void draw_cairo(CairoCanvas& c, const Workload& w, bool clear_white = true, double ink = 0) {
  cairo_t* cr = c.cr;
  cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
  if (clear_white) cairo_set_source_rgba(cr, 1, 1, 1, 1); else cairo_set_source_rgba(cr, 0, 0, 0, 0);
  cairo_paint(cr);
  cairo_set_operator(cr, CAIRO_OPERATOR_OVER);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
  cairo_set_source_rgba(cr, ink, ink, ink, 1);
  cairo_set_line_width(cr, w.width);
  cairo_set_line_join(cr, w.join == sr::Join::Round ? CAIRO_LINE_JOIN_ROUND
                          : w.join == sr::Join::Bevel ? CAIRO_LINE_JOIN_BEVEL : CAIRO_LINE_JOIN_MITER);
  cairo_set_line_cap(cr, w.cap == sr::Cap::Round ? CAIRO_LINE_CAP_ROUND
                         : w.cap == sr::Cap::Square ? CAIRO_LINE_CAP_SQUARE : CAIRO_LINE_CAP_BUTT);
  cairo_set_miter_limit(cr, 4);
  for (const Path& p : w.paths) {
    cairo_move_to(cr, p.pts[0].x, p.pts[0].y);
    for (std::size_t i = 1; i < p.pts.size(); ++i) cairo_line_to(cr, p.pts[i].x, p.pts[i].y);
    cairo_stroke(cr);
  }
  cairo_surface_flush(c.surface);
}

// ---- AGG -------------------------------------------------------------------------------
struct AggCanvas {
  std::vector<unsigned char> buf;
  agg::rendering_buffer rbuf;
  agg::pixfmt_rgba32 pixf;
  agg::renderer_base<agg::pixfmt_rgba32> ren;
  explicit AggCanvas(int size = kSize)
      : buf(static_cast<std::size_t>(size) * size * 4), rbuf(buf.data(), size, size, size * 4), pixf(rbuf), ren(pixf) {}
};

void draw_agg(AggCanvas& c, const Workload& w, bool clear_white = true, unsigned char ink = 0) {
  c.ren.clear(clear_white ? agg::rgba8(255, 255, 255, 255) : agg::rgba8(0, 0, 0, 0));
  agg::rasterizer_scanline_aa<> ras;
  agg::scanline_u8 sl;
  agg::renderer_scanline_aa_solid<agg::renderer_base<agg::pixfmt_rgba32>> solid(c.ren);
  solid.color(agg::rgba8(ink, ink, ink, 255));
  agg::path_storage path;
  agg::conv_stroke<agg::path_storage> stroke(path);
  stroke.width(w.width);
  stroke.line_join(w.join == sr::Join::Round ? agg::round_join
                   : w.join == sr::Join::Bevel ? agg::bevel_join : agg::miter_join_revert);
  stroke.line_cap(w.cap == sr::Cap::Round ? agg::round_cap : w.cap == sr::Cap::Square ? agg::square_cap : agg::butt_cap);
  stroke.miter_limit(4);
  for (const Path& p : w.paths) {
    path.remove_all();
    path.move_to(p.pts[0].x, p.pts[0].y);
    for (std::size_t i = 1; i < p.pts.size(); ++i) path.line_to(p.pts[i].x, p.pts[i].y);
    ras.reset();
    ras.add_path(stroke);
    agg::render_scanlines(ras, sl, solid);
  }
}

// ---- Blend2D ---------------------------------------------------------------------------
#ifdef SPLINEFIG_HAVE_BLEND2D
constexpr bool kHaveBlend2D = true;

struct Blend2DCanvas {
  BLImage img;
  explicit Blend2DCanvas(int size = kSize) : img(size, size, BL_FORMAT_PRGB32) {}
};

// As Cairo and AGG: one path per stroke call, the same width, join (miter falling back to bevel
// beyond the limit, as Cairo's and AGG's miter_join_revert), cap and miter limit 4. The context is
// synchronous (thread_count 0: every call renders on this thread) and end() flushes it.
void draw_blend2d(Blend2DCanvas& c, const Workload& w, bool clear_white = true, std::uint8_t ink = 0) {
  BLContextCreateInfo info{};
  info.thread_count = 0;
  BLContext ctx;
  if (ctx.begin(c.img, info) != BL_SUCCESS) {
    std::fprintf(stderr, "bench_stroke: Blend2D could not begin a context\n");
    std::exit(1);
  }
  ctx.set_comp_op(BL_COMP_OP_SRC_COPY);
  if (clear_white) ctx.fill_all(BLRgba32(0xFFFFFFFFu)); else ctx.clear_all();
  ctx.set_comp_op(BL_COMP_OP_SRC_OVER);
  ctx.set_stroke_style(BLRgba32(ink, ink, ink, 255));
  ctx.set_stroke_width(w.width);
  ctx.set_stroke_join(w.join == sr::Join::Round ? BL_STROKE_JOIN_ROUND
                      : w.join == sr::Join::Bevel ? BL_STROKE_JOIN_BEVEL : BL_STROKE_JOIN_MITER_BEVEL);
  ctx.set_stroke_caps(w.cap == sr::Cap::Round ? BL_STROKE_CAP_ROUND
                      : w.cap == sr::Cap::Square ? BL_STROKE_CAP_SQUARE : BL_STROKE_CAP_BUTT);
  ctx.set_stroke_miter_limit(4);
  BLPath path;
  for (const Path& p : w.paths) {
    path.clear();
    path.move_to(p.pts[0].x, p.pts[0].y);
    for (std::size_t i = 1; i < p.pts.size(); ++i) path.line_to(p.pts[i].x, p.pts[i].y);
    ctx.stroke_path(path);
  }
  ctx.end();
}

// Alpha of pixel (x, y) of a PRGB32 image (0xAARRGGBB words).
double blend2d_alpha(const Blend2DCanvas& c, int x, int y) {
  BLImageData d;
  c.img.get_data(&d);
  const auto* row = static_cast<const std::uint8_t*>(d.pixel_data) + static_cast<std::ptrdiff_t>(y) * d.stride;
  std::uint32_t px;
  std::memcpy(&px, row + 4 * x, 4);
  return (px >> 24) / 255.0;
}
#else
constexpr bool kHaveBlend2D = false;
#endif
constexpr const char* kBlend2DAbsent =
    "Blend2D absent: configure with -DSPLINEFIG_BLEND2D_SOURCE_DIR=<blend2d checkout> (bench/CMakeLists.txt)";

// ---- timed benchmarks ------------------------------------------------------------------
void BM_splinefig(benchmark::State& state, char id, int threads, double tolerance) {
  const Workload& w = workload(id);
  for (auto _ : state) {
    splinefig::Image img = draw_splinefig(w, threads, kSize, {1, 1, 1, 1}, {0, 0, 0, 1}, tolerance);
    benchmark::DoNotOptimize(img.pixels.data());
  }
}

// rasterize alone, the scene recorded once before the timing: what the threads share (recording
// runs on the caller's thread whatever the thread count).
void BM_splinefig_raster(benchmark::State& state, char id, int threads) {
  const sr::Scene s = splinefig_scene(workload(id), kSize, {1, 1, 1, 1}, {0, 0, 0, 1}, sr::kDefaultCoverageTolerance);
  for (auto _ : state) {
    splinefig::Image img = sr::rasterize(s, threads);
    benchmark::DoNotOptimize(img.pixels.data());
  }
}

void BM_cairo(benchmark::State& state, char id) {
  const Workload& w = workload(id);
  CairoCanvas c;
  for (auto _ : state) {
    draw_cairo(c, w);
    benchmark::DoNotOptimize(cairo_image_surface_get_data(c.surface));
  }
}

void BM_agg(benchmark::State& state, char id) {
  const Workload& w = workload(id);
  AggCanvas c;
  for (auto _ : state) {
    draw_agg(c, w);
    benchmark::DoNotOptimize(c.buf.data());
  }
}

void BM_blend2d(benchmark::State& state, [[maybe_unused]] char id) {
#ifdef SPLINEFIG_HAVE_BLEND2D
  const Workload& w = workload(id);
  Blend2DCanvas c;
  for (auto _ : state) {
    draw_blend2d(c, w);
    BLImageData d;
    c.img.get_data(&d);
    benchmark::DoNotOptimize(d.pixel_data);
  }
#else
  state.SkipWithError(kBlend2DAbsent);
#endif
}

// ---- peak memory, each drawing in a fresh child process --------------------------------
// impl: 0 splinefig, 1 Cairo, 2 AGG; threads for splinefig only.
void BM_memory(benchmark::State& state, char id, int impl, int threads) {
  double input = 0, added = 0;
  for (auto _ : state) {
    input = bench::peak_added_mb([] {}, [&] {
      Workload w = make_workload(id);
      benchmark::DoNotOptimize(w.paths.data());
    });
    Workload w;
    added = bench::peak_added_mb([&] { w = make_workload(id); }, [&] {
      if (impl == 0) {
        splinefig::Image img = draw_splinefig(w, threads);
        benchmark::DoNotOptimize(img.pixels.data());
      } else if (impl == 3) {
        splinefig::Image img = draw_splinefig_moved(std::move(w), threads);
        benchmark::DoNotOptimize(img.pixels.data());
      } else if (impl == 1) {
        CairoCanvas c;
        draw_cairo(c, w);
      } else {
        AggCanvas c;
        draw_agg(c, w);
      }
    });
  }
  state.counters["input_MB"] = input;
  state.counters["added_MB"] = added;
}

// ---- accuracy against the exact union oracle -------------------------------------------
// Two sets: "random", 27 short random polylines on 40^2; "walks", 180 seeded walks of 60 points
// on 64^2 built to reach the outline's hard cases (oracle/sharp_walks.hpp: hairpins,
// near-reversals, segments shorter than the half-width), widths 1 to 7, every join and cap.
struct AccuracyCase {
  Workload w;
  int size;
  std::vector<double> want;
};

AccuracyCase oracle_case(Workload w, int size) {
  std::vector<oracle::P2> op;
  for (auto q : w.paths[0].pts) op.push_back({q.x, q.y});
  auto pieces = oracle::stroke_pieces(op, false, w.width, static_cast<oracle::Join>(static_cast<int>(w.join)), 4,
                                      static_cast<oracle::Cap>(static_cast<int>(w.cap)));
  return {std::move(w), size, oracle::union_coverage(pieces, size, size)};
}

std::vector<AccuracyCase> accuracy_cases(bool walks) {
  std::vector<AccuracyCase> cases;
  const sr::Join joins[] = {sr::Join::Miter, sr::Join::Round, sr::Join::Bevel};
  const sr::Cap caps[] = {sr::Cap::Butt, sr::Cap::Round, sr::Cap::Square};
  if (walks) {
    std::mt19937_64 rng(20261203);
    for (int k = 0; k < 180; ++k) {
      const double width = std::array{1.0, 2.0, 3.0, 4.0, 7.0}[static_cast<std::size_t>(k / 9 % 5)];
      Workload w{{}, width, joins[k % 3], caps[(k / 3) % 3]};
      Path p;
      for (auto q : oracle::sharp_walk(rng, 60, width, 10, 54)) p.pts.push_back({q.x, q.y});
      w.paths.push_back(std::move(p));
      cases.push_back(oracle_case(std::move(w), 64));
    }
    return cases;
  }
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 27; ++k) {
    Workload w{{}, std::exp(std::log(0.1) + (std::log(20) - std::log(0.1)) * u(rng)), joins[k % 3], caps[(k / 3) % 3]};
    Path p;
    const int n = k < 18 ? 2 + k % 4 : 20;
    for (int i = 0; i < n; ++i) p.pts.push_back({6 + 28 * u(rng), 6 + 28 * u(rng)});
    if (k >= 18) w.width = 0.3 + 2.5 * u(rng);
    w.paths.push_back(std::move(p));
    cases.push_back(oracle_case(std::move(w), 40));
  }
  return cases;
}

void BM_accuracy(benchmark::State& state, int impl, bool walks) {
  if (impl == 3 && !kHaveBlend2D) return state.SkipWithError(kBlend2DAbsent);
  static const auto random_cases = accuracy_cases(false);
  static const auto walk_cases = accuracy_cases(true);
  const auto& cases = walks ? walk_cases : random_cases;
  double max_err = 0, sum = 0;
  std::size_t count = 0;
  for (auto _ : state) {
    max_err = 0; sum = 0; count = 0;
    for (const auto& [w, n, want] : cases) {
      std::vector<double> got(want.size());
      if (impl == 0) {
        splinefig::Image img = draw_splinefig(w, 1, n, {0, 0, 0, 0}, {1, 1, 1, 1});
        for (std::size_t i = 0; i < got.size(); ++i) got[i] = img.pixels[i * 4 + 3];
      } else if (impl == 1) {
        CairoCanvas c(n);
        draw_cairo(c, w, false, 1);
        const unsigned char* d = cairo_image_surface_get_data(c.surface);
        const int stride = cairo_image_surface_get_stride(c.surface);
        for (int y = 0; y < n; ++y)
          for (int x = 0; x < n; ++x) got[static_cast<std::size_t>(y * n + x)] = d[y * stride + x * 4 + 3] / 255.0;
      } else if (impl == 2) {
        AggCanvas c(n);
        draw_agg(c, w, false, 255);
        for (std::size_t i = 0; i < got.size(); ++i) got[i] = c.buf[i * 4 + 3] / 255.0;
      } else {
#ifdef SPLINEFIG_HAVE_BLEND2D
        Blend2DCanvas c(n);
        draw_blend2d(c, w, false, 255);
        for (int y = 0; y < n; ++y)
          for (int x = 0; x < n; ++x) got[static_cast<std::size_t>(y * n + x)] = blend2d_alpha(c, x, y);
#endif
      }
      for (std::size_t i = 0; i < got.size(); ++i) {
        if (got[i] == 0 && want[i] == 0) continue;
        double d = std::abs(got[i] - want[i]);
        max_err = std::max(max_err, d);
        sum += d;
        ++count;
      }
    }
  }
  state.counters["max_err"] = max_err;
  state.counters["mean_err"] = count ? sum / static_cast<double>(count) : 0;
}

// ---- dense workloads against the exact union oracle, in windows --------------------------
// The dense workloads drawn at the default coverage tolerance (one thread, black on white, so
// coverage is 1 - red in linear light), compared in two windows of `win`^2 pixels with the union
// oracle of the pieces meeting each window (the oracle's cost grows with the square of the pieces
// per pixel, so R1M, about 500 pieces a pixel and minutes a pixel, is left out). Counters: max_err, mean_err (over the windows' pixels),
// piece_bands and bands (RasterReport: how many bands were resolved from the pieces), tolerance.
void BM_dense_accuracy(benchmark::State& state, char id, int win) {
  const Workload& w = workload(id);
  double max_err = 0, sum = 0;
  std::size_t count = 0;
  sr::RasterReport report;
  for (auto _ : state) {
    const splinefig::Image img = draw_splinefig(w, 1, kSize, {1, 1, 1, 1}, {0, 0, 0, 1}, sr::kDefaultCoverageTolerance, &report);
    // Each path is its own item, composited over the others: a pixel's coverage is
    // 1 - prod(1 - c_i) over the paths' own union coverages c_i.
    std::vector<std::vector<oracle::Poly>> pieces;
    for (const Path& path : w.paths) {
      std::vector<oracle::P2> op;
      for (auto q : path.pts) op.push_back({q.x, q.y});
      pieces.push_back(oracle::stroke_pieces(op, false, w.width, static_cast<oracle::Join>(static_cast<int>(w.join)), 4,
                                             static_cast<oracle::Cap>(static_cast<int>(w.cap))));
    }
    max_err = 0, sum = 0, count = 0;
    for (auto [x0, y0] : {std::pair{kSize * 3 / 10, kSize * 3 / 10}, std::pair{kSize * 6 / 10, kSize / 2 + 7}}) {
      std::vector<double> clear(static_cast<std::size_t>(win * win), 1.0);  // prod(1 - c_i)
      for (const std::vector<oracle::Poly>& path : pieces) {
        std::vector<oracle::Poly> local;
        for (const oracle::Poly& poly : path) {
          double bx0 = INFINITY, by0 = INFINITY, bx1 = -INFINITY, by1 = -INFINITY;
          for (auto q : poly) bx0 = std::min(bx0, q.x), by0 = std::min(by0, q.y), bx1 = std::max(bx1, q.x), by1 = std::max(by1, q.y);
          if (bx1 <= x0 || bx0 >= x0 + win || by1 <= y0 || by0 >= y0 + win) continue;
          oracle::Poly moved;
          for (auto q : poly) moved.push_back({q.x - x0, q.y - y0});
          local.push_back(std::move(moved));
        }
        if (local.empty()) continue;
        const std::vector<double> c = oracle::union_coverage(local, win, win);
        for (std::size_t k = 0; k < c.size(); ++k) clear[k] *= 1 - c[k];
      }
      std::vector<double> want(clear.size());
      for (std::size_t k = 0; k < want.size(); ++k) want[k] = 1 - clear[k];
      for (int y = 0; y < win; ++y)
        for (int x = 0; x < win; ++x) {
          const double got = 1.0 - img.pixels[(static_cast<std::size_t>(y0 + y) * kSize + static_cast<std::size_t>(x0 + x)) * 4];
          const double d = std::abs(got - want[static_cast<std::size_t>(y * win + x)]);
          max_err = std::max(max_err, d);
          sum += d;
          ++count;
        }
    }
  }
  int bands = 0, piece_bands = 0;
  for (const auto& it : report.items) bands += it.bands, piece_bands += it.piece_bands;
  state.counters["max_err"] = max_err;
  state.counters["mean_err"] = count ? sum / static_cast<double>(count) : 0;
  state.counters["piece_bands"] = piece_bands;
  state.counters["bands"] = bands;
  state.counters["tolerance"] = report.tolerance;
}

void register_all() {
  const int all = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const double tol = sr::kDefaultCoverageTolerance;
  for (auto [id, name] : {std::pair{'1', "A1"}, {'3', "A3"}, {'B', "B"}, {'C', "C"}, {'u', "R1k"}, {'v', "R10k"},
                          {'x', "R30k"}, {'y', "R100k"}, {'z', "R1M"}, {'w', "Rw100k"}, {'W', "Rw1M"}}) {
    std::string base = std::string("stroke/") + name + "/";
    benchmark::RegisterBenchmark((base + "splinefig").c_str(), BM_splinefig, id, 1, tol)->Unit(benchmark::kMillisecond);
    // The exact sweep of the outline only (coverage tolerance 0), where the default resolves
    // dense bands from the pieces.
    if (id != '1' && id != '3' && id != 'B')
      benchmark::RegisterBenchmark((base + "splinefig-exact").c_str(), BM_splinefig, id, 1, 0.0)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((base + "splinefig-mt").c_str(), BM_splinefig, id, all, tol)->Unit(benchmark::kMillisecond)->UseRealTime();
    if (id == '1' || id == '3' || id == 'B' || id == 'C') {
      benchmark::RegisterBenchmark((base + "rasterize").c_str(), BM_splinefig_raster, id, 1)->Unit(benchmark::kMillisecond)->UseRealTime();
      benchmark::RegisterBenchmark((base + "rasterize-mt").c_str(), BM_splinefig_raster, id, all)->Unit(benchmark::kMillisecond)->UseRealTime();
    }
    benchmark::RegisterBenchmark((base + "cairo").c_str(), BM_cairo, id)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((base + "agg").c_str(), BM_agg, id)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((base + "blend2d").c_str(), BM_blend2d, id)->Unit(benchmark::kMillisecond);
  }
  for (auto [id, name] : {std::pair{'1', "A1"}, {'3', "A3"}, {'B', "B"}, {'C', "C"}}) {
    std::string base = std::string("memory/") + name + "/";
    benchmark::RegisterBenchmark((base + "splinefig").c_str(), BM_memory, id, 0, 1)->Iterations(1)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((base + "splinefig-mt").c_str(), BM_memory, id, 0, all)->Iterations(1)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((base + "splinefig-moved").c_str(), BM_memory, id, 3, 1)->Iterations(1)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((base + "cairo").c_str(), BM_memory, id, 1, 1)->Iterations(1)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((base + "agg").c_str(), BM_memory, id, 2, 1)->Iterations(1)->Unit(benchmark::kMillisecond);
  }
  for (auto [id, name, win] : {std::tuple{'C', "C", 16}, {'v', "R10k", 16}, {'x', "R30k", 16}, {'y', "R100k", 12},
                               {'w', "Rw100k", 16}, {'W', "Rw1M", 16}})
    benchmark::RegisterBenchmark((std::string("accuracy/dense/") + name).c_str(), BM_dense_accuracy, id, win)
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  for (auto [walks, set] : {std::pair{false, "random"}, {true, "walks"}})
    for (auto [impl, name] : {std::pair{0, "splinefig"}, {1, "cairo"}, {2, "agg"}, {3, "blend2d"}})
      benchmark::RegisterBenchmark((std::string("accuracy/") + set + "/" + name).c_str(), BM_accuracy, impl, walks)
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
}

}  // namespace

// The console report, then the ratio table of the stroke workloads that ran: splinefig's
// one-thread CPU time against Cairo's, AGG's and Blend2D's (goals: 2x Cairo, 1.5x AGG, 1x
// Blend2D), and its speed-up on all threads in wall time (goal for A1, A3, B and C: 1.8x on 2
// cores).
// With repetitions, the medians are used. Without Blend2D its cells read "absent".
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  RatioReporter() : ConsoleReporter(isatty(fileno(stdout)) ? OO_Defaults : OO_Tabular) {}
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.error_occurred || (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median")) continue;
      const std::string& name = r.run_name.function_name;  // stroke/<workload>/<impl>
      if (name.rfind("stroke/", 0) != 0) continue;
      const std::size_t slash = name.find('/', 7);
      if (slash == std::string::npos) continue;
      const std::string workload = name.substr(7, slash - 7), impl = name.substr(slash + 1);
      if (std::find(order_.begin(), order_.end(), workload) == order_.end()) order_.push_back(workload);
      times_[workload][impl] = {r.GetAdjustedCPUTime(), r.GetAdjustedRealTime()};
    }
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    if (order_.empty()) return;
    std::FILE* out = stdout;
    std::fprintf(out, "\nsplinefig against the peers (1 thread, CPU ms; speed-up on %u threads, wall):\n",
                 std::max(1u, std::thread::hardware_concurrency()));
#ifdef SPLINEFIG_HAVE_BLEND2D
    std::fprintf(out, "(Blend2D %u.%u.%u, synchronous, 1 thread)\n", BL_VERSION >> 16, (BL_VERSION >> 8) & 0xFFu,
                 BL_VERSION & 0xFFu);
#endif
    std::fprintf(out, "%-8s %11s %11s %11s %11s %9s %9s %10s %9s %10s\n", "workload", "splinefig", "cairo", "agg",
                 "blend2d", "vs cairo", "vs agg", "vs blend2d", "threads", "rasterize");
    auto cell = [&](const std::map<std::string, Times>& t, const char* impl, bool cpu) {
      auto it = t.find(impl);
      return it == t.end() ? -1.0 : (cpu ? it->second.cpu : it->second.real);
    };
    auto ratio = [](double a, double b, double goal) {
      char buf[32];
      if (a <= 0 || b <= 0) return std::string("-");
      std::snprintf(buf, sizeof buf, "%.2fx%s", b / a, b / a >= goal ? "" : "*");
      return std::string(buf);
    };
    for (const std::string& w : order_) {
      const auto& t = times_[w];
      const double sf = cell(t, "splinefig", true), ca = cell(t, "cairo", true), ag = cell(t, "agg", true),
                   bl = cell(t, "blend2d", true);
      const double sf_wall = cell(t, "splinefig", false), mt_wall = cell(t, "splinefig-mt", false);
      const double r_wall = cell(t, "rasterize", false), rmt_wall = cell(t, "rasterize-mt", false);
      const bool scaled = w == "A1" || w == "A3" || w == "B" || w == "C";
      char bl_cell[16];
      if (bl > 0) std::snprintf(bl_cell, sizeof bl_cell, "%.1f", bl); else std::snprintf(bl_cell, sizeof bl_cell, "%s", kHaveBlend2D ? "-" : "absent");
      std::fprintf(out, "%-8s %11.1f %11.1f %11.1f %11s %9s %9s %10s %9s %10s\n", w.c_str(), sf, ca, ag, bl_cell,
                   ratio(sf, ca, 2).c_str(), ratio(sf, ag, 1.5).c_str(),
                   kHaveBlend2D ? ratio(sf, bl, 1).c_str() : "absent", ratio(mt_wall, sf_wall, scaled ? 1.8 : 0).c_str(),
                   ratio(rmt_wall, r_wall, 0).c_str());
    }
    std::fprintf(out, "* below the goal (2x Cairo, 1.5x AGG, 1x Blend2D; threads: 1.8x for A1, A3, B and C)\n"
                      "threads: the whole drawing (recording the scene, then rasterize); rasterize: rasterize alone\n");
    if (!kHaveBlend2D) std::fprintf(out, "%s\n", kBlend2DAbsent);
  }

 private:
  struct Times {
    double cpu = -1, real = -1;
  };
  std::vector<std::string> order_;
  std::map<std::string, std::map<std::string, Times>> times_;
};

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
