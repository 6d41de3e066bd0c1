// Curve evaluation throughput: a 10^6-knot 3-D curve at grain 16 (about 1.6e7 points),
// Catmull-Rom and B-spline, three ways in the same binary:
//   eval/<basis>/splinefig   splinefig::sample_into (weight table once, contiguous output)
//   eval/<basis>/memo        the memo's appendix routine with its bugs fixed (docs/errata.md): a
//                            Matrix() call per coordinate per point, alpha table per grain
//   eval/<basis>/glm         glm::catmullRom per point (gtx/spline); GLM has no B-spline, so
//                            the B-spline uses glm::cubic on the piece's Horner coefficients
//                            (B times the four knots, computed once per piece)
//   eval/write-floor         only writes the same number of 3-D points with ordinary stores
//   eval/write-floor-streamed  the same with non-temporal stores, as the sampler writes an output
//                            this large (the memory limit)
// Items are output points; every variant writes into the same preallocated buffer.
#define GLM_ENABLE_EXPERIMENTAL
#include <benchmark/benchmark.h>
#include <glm/glm.hpp>
#include <glm/gtx/spline.hpp>
#include <splinefig/spline/curve.hpp>

#include <cstdint>
#include <vector>

#if defined(__x86_64__) && defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace {

constexpr std::size_t knot_count = 1000000;
constexpr int grain = 16;
constexpr std::size_t point_count = (knot_count - 3) * grain + 1;

const splinefig::Points& knots() {
  static const splinefig::Points k = [] {
    splinefig::Points p(3, knot_count);
    std::uint64_t s = 0x9E3779B97F4A7C15ull;  // xorshift: deterministic knots in [-1, 1]
    for (double& x : p.coords) {
      s ^= s << 13;
      s ^= s >> 7;
      s ^= s << 17;
      x = static_cast<double>(s >> 11) * 0x1p-52 - 1.0;
    }
    return p;
  }();
  return k;
}

// One output buffer for all variants, touched once so no run pays for page faults.
std::vector<double>& output() {
  static std::vector<double> out(point_count * 3, 1.0);
  return out;
}

// ---- The memo's appendix routine, corrected: segments i = 1..n-3, grain points each at
// alpha[j] = j/grain, then the final point u = 1; n >= 4, grain >= 1; no static buffer.
struct point {
  double x, y, z;
};
using matrix = double[4][4];

double Matrix(double a, double b, double c, double d, double alpha, const matrix m) {
  const double p0 = m[0][0] * a + m[0][1] * b + m[0][2] * c + m[0][3] * d;
  const double p1 = m[1][0] * a + m[1][1] * b + m[1][2] * c + m[1][3] * d;
  const double p2 = m[2][0] * a + m[2][1] * b + m[2][2] * c + m[2][3] * d;
  const double p3 = m[3][0] * a + m[3][1] * b + m[3][2] * c + m[3][3] * d;
  return p3 + alpha * (p2 + alpha * (p1 + alpha * p0));
}

// Returns the number of points written: (n-3)*grain + 1, or 0 on bad arguments.
std::size_t CubicSpline(std::size_t n, const point* knots, int grain, const matrix m, point* s) {
  if (n < 4 || grain < 1) return 0;
  std::vector<double> alpha(static_cast<std::size_t>(grain));
  for (int i = 0; i < grain; i++) alpha[static_cast<std::size_t>(i)] = static_cast<double>(i) / grain;
  const point *km1 = knots, *k0 = km1 + 1, *k1 = k0 + 1, *k2 = k1 + 1;
  point* out = s;
  for (std::size_t i = 1; i <= n - 3; i++) {
    for (int j = 0; j < grain; j++) {
      const double a = alpha[static_cast<std::size_t>(j)];
      out->x = Matrix(km1->x, k0->x, k1->x, k2->x, a, m);
      out->y = Matrix(km1->y, k0->y, k1->y, k2->y, a, m);
      (out++)->z = Matrix(km1->z, k0->z, k1->z, k2->z, a, m);
    }
    km1++, k0++, k1++, k2++;
  }
  km1--, k0--, k1--, k2--;  // the final point: u = 1 of the last segment
  out->x = Matrix(km1->x, k0->x, k1->x, k2->x, 1.0, m);
  out->y = Matrix(km1->y, k0->y, k1->y, k2->y, 1.0, m);
  (out++)->z = Matrix(km1->z, k0->z, k1->z, k2->z, 1.0, m);
  return static_cast<std::size_t>(out - s);
}

void set_matrix(const splinefig::Basis& b, matrix m) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[r][c] = b(r, c);
}

void items(benchmark::State& state) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(point_count));
  state.counters["points"] = static_cast<double>(point_count);
}

void eval_splinefig(benchmark::State& state, const splinefig::Basis& basis) {
  const splinefig::Curve c = splinefig::make_curve(basis, knots(), splinefig::Ends::open);
  std::vector<double>& out = output();
  for (auto _ : state) {
    splinefig::sample_into(c, grain, 0, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  items(state);
}

void eval_memo(benchmark::State& state, const splinefig::Basis& basis) {
  matrix m;
  set_matrix(basis, m);
  const auto* k = reinterpret_cast<const point*>(knots().coords.data());
  auto* s = reinterpret_cast<point*>(output().data());
  for (auto _ : state) {
    benchmark::DoNotOptimize(CubicSpline(knot_count, k, grain, m, s));
    benchmark::ClobberMemory();
  }
  items(state);
}

void eval_glm_catmull_rom(benchmark::State& state) {
  const auto* k = reinterpret_cast<const glm::dvec3*>(knots().coords.data());
  auto* o = reinterpret_cast<glm::dvec3*>(output().data());
  for (auto _ : state) {
    glm::dvec3* p = o;
    for (std::size_t i = 0; i + 3 < knot_count; ++i)
      for (int j = 0; j < grain; ++j) *p++ = glm::catmullRom(k[i], k[i + 1], k[i + 2], k[i + 3], j / double(grain));
    *p = glm::catmullRom(k[knot_count - 4], k[knot_count - 3], k[knot_count - 2], k[knot_count - 1], 1.0);
    benchmark::DoNotOptimize(o);
    benchmark::ClobberMemory();
  }
  items(state);
}

void eval_glm_bspline(benchmark::State& state) {
  const auto* k = reinterpret_cast<const glm::dvec3*>(knots().coords.data());
  auto* o = reinterpret_cast<glm::dvec3*>(output().data());
  // Rows of the memo's B: the cubic's coefficients are B (x[i-1] x[i] x[i+1] x[i+2])^T.
  const double B[4][4] = {{-1 / 6.0, 3 / 6.0, -3 / 6.0, 1 / 6.0},
                          {3 / 6.0, -6 / 6.0, 3 / 6.0, 0},
                          {-3 / 6.0, 0, 3 / 6.0, 0},
                          {1 / 6.0, 4 / 6.0, 1 / 6.0, 0}};
  auto coef = [&](std::size_t i, int r) {
    return B[r][0] * k[i] + B[r][1] * k[i + 1] + B[r][2] * k[i + 2] + B[r][3] * k[i + 3];
  };
  for (auto _ : state) {
    glm::dvec3* p = o;
    for (std::size_t i = 0; i + 3 < knot_count; ++i) {
      const glm::dvec3 a = coef(i, 0), b = coef(i, 1), c = coef(i, 2), d = coef(i, 3);
      for (int j = 0; j < grain; ++j) *p++ = glm::cubic(a, b, c, d, j / double(grain));
    }
    const std::size_t i = knot_count - 4;
    *p = glm::cubic(coef(i, 0), coef(i, 1), coef(i, 2), coef(i, 3), 1.0);
    benchmark::DoNotOptimize(o);
    benchmark::ClobberMemory();
  }
  items(state);
}

void eval_write_floor(benchmark::State& state) {
  std::vector<double>& out = output();
  for (auto _ : state) {
    double* p = out.data();
    for (std::size_t i = 0; i < point_count; ++i, p += 3) {
      p[0] = 1.0;
      p[1] = 2.0;
      p[2] = 3.0;
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  items(state);
}

void eval_write_floor_streamed(benchmark::State& state) {
#if defined(__x86_64__) && defined(__SSE2__)
  std::vector<double>& out = output();
  const __m128d a = _mm_set_pd(2.0, 1.0), b = _mm_set_pd(1.0, 3.0), c = _mm_set_pd(3.0, 2.0);
  for (auto _ : state) {
    double* p = out.data();
    for (std::size_t i = 0; i + 1 < point_count; i += 2, p += 6) {  // 16-byte aligned (the vector's storage)
      _mm_stream_pd(p, a);
      _mm_stream_pd(p + 2, b);
      _mm_stream_pd(p + 4, c);
    }
    _mm_sfence();
    p[0] = 1.0, p[1] = 2.0, p[2] = 3.0;  // point_count is odd
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  items(state);
#else
  state.SkipWithError("no SSE2 streaming stores on this target");
#endif
}

}  // namespace

BENCHMARK_CAPTURE(eval_splinefig, catmull_rom, splinefig::catmull_rom())->Name("eval/catmull-rom/splinefig")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_memo, catmull_rom, splinefig::catmull_rom())->Name("eval/catmull-rom/memo")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_glm_catmull_rom)->Name("eval/catmull-rom/glm")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_splinefig, bspline, splinefig::bspline())->Name("eval/bspline/splinefig")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(eval_memo, bspline, splinefig::bspline())->Name("eval/bspline/memo")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_glm_bspline)->Name("eval/bspline/glm")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_write_floor)->Name("eval/write-floor")->Unit(benchmark::kMillisecond);
BENCHMARK(eval_write_floor_streamed)->Name("eval/write-floor-streamed")->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
