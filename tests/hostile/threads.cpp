// The resampler's library entry point bounds the worker count as the command line does: a
// count of INT_MAX gives the bytes of one thread, no overflow in the chunk arithmetic.
#include <splinefig/base/limits.hpp>
#include <splinefig/base/parallel.hpp>
#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <catch2/catch.hpp>

#include <climits>

TEST_CASE("resample with INT_MAX threads gives the result of one thread") {
  using namespace splinefig;
  Image src(37, 23, 3);
  for (std::size_t i = 0; i < src.pixels.size(); ++i) src.pixels[i] = float((i * 7919) % 101) / 100.0f;
  const Kernel k = parse_kernel("catmull-rom");
  ResampleOptions one, huge;
  one.threads = 1;
  huge.threads = INT_MAX;
  CHECK(worker_count(INT_MAX) == kMaxThreads);
  const Image a = resample(src, 300, 200, k, one), b = resample(src, 300, 200, k, huge);
  CHECK(a.pixels == b.pixels);
}
