// The inverse prefilter: the systems it solves are checked by substituting the solution back
// (the defining equations, not the algorithm), and resampling to the same size after it
// returns the input.
#include <catch2/catch.hpp>

#include <splinefig/resample/prefilter.hpp>
#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <cmath>
#include <random>

using namespace splinefig;

namespace {

Image random_image(int w, int h, int c, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Image img(w, h, c);
  for (auto& v : img.pixels) v = u(rng);
  return img;
}

long extended(long j, long n, Edge e) {  // -1 for black
  if (j >= 0 && j < n) return j;
  if (e == Edge::black) return -1;
  if (e == Edge::wrap) return (j + n) % n;
  return j < 0 ? 0 : n - 1;  // clamp and mirror agree one sample out
}

}  // namespace

TEST_CASE("the B-spline prefilter solves the 1-4-1 system with each edge extension") {
  for (Edge e : {Edge::clamp, Edge::mirror, Edge::wrap, Edge::black})
    for (long n : {1L, 2L, 3L, 5L, 64L, 5000L}) {
      std::mt19937 rng(static_cast<unsigned>(n));
      std::uniform_real_distribution<float> u(-1, 1);
      std::vector<float> p(static_cast<size_t>(n));
      for (auto& v : p) v = u(rng);
      std::vector<float> c = p;
      prefilter_line(c.data(), n, 1, sampled_kernel(parse_kernel("bspline")), e);
      INFO(edge_name(e) << " n = " << n);
      double worst = 0;
      for (long i = 0; i < n; ++i) {
        auto at = [&](long j) {
          const long k = extended(j, n, e);
          return k < 0 ? 0.0 : double(c[static_cast<size_t>(k)]);
        };
        worst = std::max(worst, std::abs((at(i - 1) + 4 * at(i) + at(i + 1)) / 6 - p[static_cast<size_t>(i)]));
      }
      CHECK(worst <= 1e-6);
    }
}

TEST_CASE("prefilter then resampling to the same size returns the input") {
  const char* specs[] = {"bspline", "tensioned-bspline:a=0.5", "beta:b1=2,b2=0", "beta:b1=0.5,b2=3",
                         "beta:b1=1,b2=5", "uniform-bspline:degree=3", "catmull-rom", "lanczos3"};
  unsigned seed = 1;
  for (const char* spec : specs)
    for (Edge e : {Edge::clamp, Edge::mirror, Edge::wrap, Edge::black})
      for (auto [w, h] : {std::pair{23, 17}, std::pair{1, 3}, std::pair{2, 2}, std::pair{300, 4}}) {
        const int channels = 1 + static_cast<int>(seed % 4);
        const Image src = random_image(w, h, channels, seed++);
        ResampleOptions opt;
        opt.edge = e;
        opt.interpolating = true;
        const Image out = resample(src, w, h, parse_kernel(spec), opt);
        double worst = 0;
        for (size_t i = 0; i < src.pixels.size(); ++i)
          worst = std::max(worst, double(std::abs(out.pixels[i] - src.pixels[i])));
        INFO(spec << " " << edge_name(e) << " " << w << "x" << h);
        CHECK(worst <= 1e-5);
      }
}

TEST_CASE("an interpolating B-spline upsampled by 3 passes through the samples") {
  // Output pixel 3m+1 has its centre at (3m + 1.5)/3 = m + 1/2, source pixel m's centre.
  const Image src = random_image(20, 14, 3, 5);
  ResampleOptions opt;
  opt.interpolating = true;
  opt.edge = Edge::mirror;
  const Image out = resample(src, 60, 42, parse_kernel("bspline"), opt);
  double worst = 0;
  for (int y = 0; y < 14; ++y)
    for (int x = 0; x < 20; ++x)
      for (int c = 0; c < 3; ++c) worst = std::max(worst, double(std::abs(out.at(3 * x + 1, 3 * y + 1, c) - src.at(x, y, c))));
  CHECK(worst <= 1e-5);
  // Without the prefilter the B-spline blurs the random samples far more than that.
  opt.interpolating = false;
  const Image blurred = resample(src, 60, 42, parse_kernel("bspline"), opt);
  CHECK(std::abs(blurred.at(31, 31, 0) - src.at(10, 10, 0)) + std::abs(blurred.at(4, 7, 1) - src.at(1, 2, 1)) > 1e-3);
}

TEST_CASE("the sampled kernel and the stability condition k(0) > 1/2") {
  const SampledKernel b = sampled_kernel(parse_kernel("bspline"));
  CHECK(b.left == Approx(1.0 / 6).epsilon(1e-15));
  CHECK(b.centre == Approx(4.0 / 6).epsilon(1e-15));
  // beta b2 = 0 is stable for (3 - sqrt 5)/2 < b1 < (3 + sqrt 5)/2 ~ 2.618.
  CHECK_NOTHROW(sampled_kernel(parse_kernel("beta:b1=2.6,b2=0")));
  CHECK_THROWS_WITH(sampled_kernel(parse_kernel("beta:b1=2.65,b2=0")), Catch::Contains("no stable inverse"));
  CHECK_THROWS_WITH(sampled_kernel(parse_kernel("beta:b1=0.37,b2=0")), Catch::Contains("no stable inverse"));
  CHECK_NOTHROW(sampled_kernel(parse_kernel("beta:b1=0.39,b2=0")));
  // The quadratic B-spline's samples (1/2, 1/2) vanish at Nyquist; the quintic spans 5 taps.
  CHECK_THROWS_WITH(sampled_kernel(parse_kernel("uniform-bspline:degree=2")), Catch::Contains("no stable inverse"));
  CHECK_THROWS_WITH(sampled_kernel(parse_kernel("uniform-bspline:degree=5")), Catch::Contains("only kernels sampled"));
  // An interpolating kernel's prefilter is the identity.
  const SampledKernel c = sampled_kernel(parse_kernel("catmull-rom"));
  CHECK(c.left == 0);
  CHECK(c.right == 0);
}
