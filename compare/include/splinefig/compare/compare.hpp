#pragma once
// One comparison of two images, the way `splinefig diff` and the Catch2 matcher do it: idiff's
// numbers and verdict (idiff.hpp) on the images as given, optionally
//   - in linear light (sRGB-encoded images decoded first),
//   - without alpha,
//   - with a mask (pixels where the mask is 0 are left out),
//   - with a shift tolerance of N pixels (shift.hpp),
//   - with SSIM and FLIP (perceptual.hpp), failing when SSIM < ssim_min or mean FLIP > flip_max;
// and its report as idiff's text lines or as JSON.
#include <splinefig/compare/idiff.hpp>
#include <splinefig/compare/image.hpp>

#include <optional>
#include <string>
#include <vector>

namespace splinefig::compare {

struct Options {
  Thresholds thresholds;
  bool linear = false;
  bool ignore_alpha = false;
  int shift = 0;
  std::optional<double> ssim_min;
  std::optional<double> flip_max;
  bool perceptual = false;  // compute SSIM and FLIP even without thresholds
  int threads = 0;
};

struct Comparison {
  Image a, b;          // as compared: after linear decoding and alpha removal
  Image pa, pb;        // the same on the union window with the union channel count
  bool sizes_differ = false;
  bool channels_differ = false;
  Metrics metrics;
  Verdict idiff = Verdict::match;  // idiff's verdict on the (shift-tolerant) numbers
  std::optional<double> ssim;
  std::optional<double> flip_mean, flip_max;
  std::vector<std::string> failures;  // perceptual checks that failed, one line each
  Verdict verdict = Verdict::match;   // idiff's verdict, made a failure by a failed check
};

// Both images are padded to the union of their windows: a union of more than kMaxPaddedPixels
// that is also more than kMaxPaddingFactor times the pixels the two windows hold (two small
// images far apart) is refused with std::length_error, as is one over union_window's limit.
inline constexpr long long kMaxPaddedPixels = 1LL << 22;
inline constexpr long long kMaxPaddingFactor = 16;

// `mask`, if given, must have the size of the union of the two windows; its first channel
// selects the compared pixels (non-zero: compared). Throws CompareError otherwise.
Comparison compare_images(const Image& a, const Image& b, const Options& options, const Image* mask = nullptr);

// idiff's output for the comparison: "Comparing" line, size/channel lines (ours), the report
// lines when the verdict is not a match (or `verbose`), our metric lines, and the verdict
// word. `quiet` prints only "FAILURE" lines as idiff -q does (to the returned text).
std::string text_report(const Comparison& c, const Options& options, const std::string& name_a,
                        const std::string& name_b, bool verbose = false, bool quiet = false);

// The same as one JSON object (non-finite numbers as the strings "inf", "-inf", "nan").
std::string json_report(const Comparison& c, const Options& options, const std::string& name_a,
                        const std::string& name_b);

// Exit code of `splinefig diff` and idiff for a verdict: 0, 1 or 2.
inline int exit_code(Verdict v) { return static_cast<int>(v); }

}  // namespace splinefig::compare
