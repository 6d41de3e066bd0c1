// The companion texts' hot paths: interpolation through 10^6 points (the 1-4-1 solve) and
// non-uniform B-spline evaluation by Cox-de Boor against the uniform matrix path on the same
// uniform knots (goals: interp < 0.1 s for 10^6 3-D points; Cox-de Boor within 3x).
#include <benchmark/benchmark.h>
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/interp.hpp>
#include <splinefig/spline/nonuniform.hpp>

#include <malloc.h>

#include <random>

using namespace splinefig;

namespace {

Points random_points(std::size_t count, int dim) {
  std::mt19937 rng(1983);
  std::uniform_real_distribution<double> d(-100, 100);
  Points p(dim, count);
  for (double& x : p.coords) x = d(rng);
  return p;
}

void BM_InterpRelaxed(benchmark::State& state) {
  const Points S = random_points(static_cast<std::size_t>(state.range(0)), 3);
  for (auto _ : state) benchmark::DoNotOptimize(interpolate_relaxed(S).control.coords.data());
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_InterpRelaxed)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_InterpPeriodic(benchmark::State& state) {
  Points S = random_points(static_cast<std::size_t>(state.range(0)), 3);
  S.push_back(std::vector<double>(S[0].begin(), S[0].end()));
  for (auto _ : state) benchmark::DoNotOptimize(interpolate_periodic(S).control.coords.data());
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_InterpPeriodic)->Arg(1000000)->Unit(benchmark::kMillisecond);

// Solve plus the curve at grain 1 (one point per datum) and the Bezier pieces: all `interp`
// does between reading and writing CSV.
void BM_InterpCurveAndBezier(benchmark::State& state) {
  const Points S = random_points(static_cast<std::size_t>(state.range(0)), 3);
  for (auto _ : state) {
    const Interpolant s = interpolate_relaxed(S);
    benchmark::DoNotOptimize(sample(s, 1).coords.data());
    benchmark::DoNotOptimize(bezier_pieces(s).points.coords.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_InterpCurveAndBezier)->Arg(1000000)->Unit(benchmark::kMillisecond);

// The same uniform cubic B-spline (10^4 control points in 3-D, grain 16) three ways.
constexpr std::size_t kControl = 10000;
constexpr int kGrain = 16;

void BM_UniformMatrixPath(benchmark::State& state) {
  const Curve c = make_curve(bspline(), random_points(kControl, 3), Ends::open);
  for (auto _ : state) benchmark::DoNotOptimize(sample(c, kGrain).coords.data());
  state.SetItemsProcessed(state.iterations() * static_cast<long>(c.segments() * kGrain + 1));
}
BENCHMARK(BM_UniformMatrixPath)->Unit(benchmark::kMillisecond);

void BM_CoxDeBoorSample(benchmark::State& state) {
  const BSplineCurve c{3, uniform_knots(kControl, 3), random_points(kControl, 3)};
  for (auto _ : state) benchmark::DoNotOptimize(sample(c, kGrain).coords.data());
  state.SetItemsProcessed(state.iterations() * static_cast<long>((kControl - 3) * kGrain + 1));
}
BENCHMARK(BM_CoxDeBoorSample)->Unit(benchmark::kMillisecond);

void BM_DeBoorPointwise(benchmark::State& state) {
  const BSplineCurve c{3, uniform_knots(kControl, 3), random_points(kControl, 3)};
  const std::size_t n = (kControl - 3) * kGrain + 1;
  Points out(3, n);
  for (auto _ : state) {
    for (std::size_t k = 0; k < n; ++k)
      de_boor(c, 3 + static_cast<double>(k) / kGrain, std::span<double>(out.coords.data() + 3 * k, 3));
    benchmark::DoNotOptimize(out.coords.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(n));
}
BENCHMARK(BM_DeBoorPointwise)->Unit(benchmark::kMillisecond);

}  // namespace

// Freed blocks stay with the process (no trimming, no fresh mmap per large vector), as in a
// long-running program: otherwise every iteration pays first-touch page faults for its
// 24 MB buffers, which on some machines cost more than the arithmetic.
int main(int argc, char** argv) {
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
