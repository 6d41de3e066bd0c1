// The C++ half of python/bench/overhead.py: the workloads of the Python calls made directly on
// the library, timed the same way (best of `reps` runs). Usage:
//   splinefig_python_overhead kernel N REPS     k(x) of Catmull-Rom at N points in [-2.5, 2.5], into a reused buffer
//   splinefig_python_overhead evaluate N REPS   a B-spline through N 2-D knots, grain 16, new and into a reused buffer
//   splinefig_python_overhead resample N REPS   an N x N RGB image to N/2 x N/2 and to 3N/2 x 3N/2 (catmull-rom)
// Prints "seconds checksum" per workload line.
#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace splinefig;

namespace {

template <class F>
double best_of(int reps, F&& f) {
  double best = 1e300;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

// The inputs overhead.py builds with numpy, by the same formulas.
double knot_x(long i) { return std::sin(0.001 * static_cast<double>(i)) * 100.0; }
double knot_y(long i) { return std::cos(0.0007 * static_cast<double>(i)) * 50.0 + 0.01 * static_cast<double>(i); }
float pixel(long i) { return static_cast<float>((i * 7919) % 1000) / 1000.0f; }

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s kernel|evaluate|resample N REPS\n", argv[0]);
    return 2;
  }
  const std::string what = argv[1];
  const long n = std::atol(argv[2]);
  const int reps = std::atoi(argv[3]);
  if (what == "kernel") {
    const Kernel k = basis_kernel(catmull_rom());
    std::vector<double> x(static_cast<std::size_t>(n)), out(x.size());
    for (long i = 0; i < n; ++i) x[static_cast<std::size_t>(i)] = -2.5 + 5.0 * static_cast<double>(i) / static_cast<double>(n - 1);
    const double s = best_of(reps, [&] {
      for (std::size_t i = 0; i < x.size(); ++i) out[i] = k(x[i]);
    });
    double sum = 0;
    for (double v : out) sum += v;
    std::printf("%.9f %.17g\n", s, sum);
  } else if (what == "evaluate") {
    Points knots(2, static_cast<std::size_t>(n));
    for (long i = 0; i < n; ++i) knots[static_cast<std::size_t>(i)][0] = knot_x(i), knots[static_cast<std::size_t>(i)][1] = knot_y(i);
    const Basis b = bspline();
    // A new result each time (sample), and into a buffer allocated once (sample_into).
    Points fresh;
    const double s = best_of(reps, [&] { fresh = sample(make_curve(b, knots, Ends::open), 16); });
    std::vector<double> out(sample_count(make_curve(b, knots, Ends::open), 16) * 2, 0.0);
    const double s2 = best_of(reps, [&] { sample_into(make_curve(b, knots, Ends::open), 16, 0, out); });
    double sum = 0, sum2 = 0;
    for (double v : fresh.coords) sum += v;
    for (double v : out) sum2 += v;
    std::printf("%.9f %.17g\n%.9f %.17g\n", s, sum, s2, sum2);
  } else if (what == "resample") {
    Image src(static_cast<int>(n), static_cast<int>(n), 3);
    for (std::size_t i = 0; i < src.pixels.size(); ++i) src.pixels[i] = pixel(static_cast<long>(i));
    const Kernel k = basis_kernel(catmull_rom());
    for (const long d : {n / 2, 3 * n / 2}) {
      Image out;
      const double s = best_of(reps, [&] { out = resample(src, static_cast<int>(d), static_cast<int>(d), k); });
      double sum = 0;
      for (float v : out.pixels) sum += v;
      std::printf("%.9f %.17g\n", s, sum);
    }
  } else {
    std::fprintf(stderr, "unknown workload %s\n", what.c_str());
    return 2;
  }
  return 0;
}
