#pragma once
// The numbers and the verdict of OpenImageIO's `idiff` (2.4), reproduced:
//
// Over the union of the two data windows and max(channels) channels, missing pixels and
// channels read as 0, every value pair gives f = |a - b| (computed in float). Then
//   mean error = sum f / nvalues,   RMS error = sqrt(sum f^2 / nvalues),
//   peak SNR   = 20 log10(maxval / RMS), maxval = max(1, largest value in either image),
//   max error  = largest f, at the first pixel (scanline order) and channel where it occurs,
//   nwarn / nfail = pixels with some channel's f > warn / fail.
// Non-finite values follow ImageBufAlgo::compare: NaN matches NaN and Inf matches Inf (the pair
// is skipped); any other pair with a non-finite value makes the max error infinite.
// Percentages and the verdict use the pixel count of the first image (idiff's npels):
//   nfail <= allowfailures                                  -> match (idiff 2.4 checks this first,
//                                                              so without failures nothing warns)
//   nfail > failpercent% of npels or max error > hardfail   -> failure
//   nwarn > warnpercent% of npels or max error > hardwarn   -> warning
//   otherwise                                               -> match
#include <splinefig/compare/image.hpp>

#include <cstdint>
#include <limits>

namespace splinefig::compare {

struct Thresholds {
  float fail = 1e-6f;
  float failpercent = 0.0f;
  float hardfail = std::numeric_limits<float>::infinity();
  float warn = 1e-6f;
  float warnpercent = 0.0f;
  float hardwarn = std::numeric_limits<float>::infinity();
  long long allowfailures = 0;
};

// ImageBufAlgo::CompareResults, plus idiff's denominator.
struct Metrics {
  double mean_error = 0.0;
  double rms_error = 0.0;
  double psnr = std::numeric_limits<double>::infinity();
  float max_error = 0.0f;
  int max_x = 0, max_y = 0, max_c = 0;  // absolute pixel coordinates, channel index
  std::uint64_t nwarn = 0;
  std::uint64_t nfail = 0;
  std::uint64_t npels = 1;    // compared pixels of the first image (idiff: width * height, >= 1)
  std::uint64_t nvalues = 0;  // values that the mean and RMS average over
};

enum class Verdict { match = 0, warning = 1, failure = 2 };

// Optional inputs beyond idiff's:
//   mask  : pixels (of the union window) whose mask value is 0 are left out of every number;
//           a 1-channel image on the union window, nullptr for none.
//   error : a tolerated error per value (e.g. from shift_tolerant_error) used instead of |a-b|
//           for finite pairs; an image on the union window with the union channel count.
//   loop  : which inner loop computes RGBA images without mask or tolerated error (every other
//           input takes the portable loop). `fastest` is AVX2 + FMA when the CPU has them, else
//           SSE2; the others force one loop, so that tests can check each on any machine. The
//           numbers are the same whichever runs.
enum class InnerLoop { fastest, avx2, sse2, portable };

struct MetricOptions {
  const Image* mask = nullptr;
  const Image* error = nullptr;
  int threads = 0;  // 0: hardware concurrency. The result does not depend on it.
  InnerLoop loop = InnerLoop::fastest;
};

// Whether this build and CPU have `loop`; idiff_metrics throws CompareError for one
// they lack.
bool inner_loop_available(InnerLoop loop);

Metrics idiff_metrics(const Image& a, const Image& b, float failthresh, float warnthresh,
                      const MetricOptions& options = {});

Verdict idiff_verdict(const Metrics& m, const Thresholds& t);

}  // namespace splinefig::compare
