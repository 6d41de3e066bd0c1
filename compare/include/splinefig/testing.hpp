#pragma once
// Catch2 (v2) support for image tests: compare a rendered image with a reference file.
//
//   #include <splinefig/testing.hpp>
//   using splinefig::testing::MatchesReference;
//   splinefig::Image img = ...;  // e.g. splinefig::render::rasterize(scene)
//   CHECK_THAT(img, MatchesReference("tests/reference/cbasis.png", {.fail = 2.0f / 255, .shift = 1}));
//
// The comparison is `splinefig diff`'s (splinefig/compare/compare.hpp). A linear image checked
// against a PNG reference is first stored as the 8-bit sRGB PNG splinefig would write and read
// back, so the test compares what the file would hold; against an EXR it is compared as is.
//
// On failure the matcher writes <stem>.actual.<ext>, <stem>.diff.png (|a-b| scaled so the
// largest difference is 1) and <stem>.triptych.png (expected | actual | heat map) to
// $SPLINEFIG_TEST_RESULTS (default build/test-results/) and its message gives their paths and
// the numbers. With SPLINEFIG_UPDATE_REFERENCES=1 it writes the image as the new reference
// instead, says so, and passes: review the change (git diff, the images) before committing.
//
// Header-only on purpose: only test code includes it, and it needs Catch2's headers.
#include <splinefig/compare/compare.hpp>
#include <splinefig/compare/visualize.hpp>
#include <splinefig/image/io.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <unistd.h>

namespace splinefig::testing {

struct Tolerance {
  float fail = 1e-6f;
  float failpercent = 0.0f;
  float warn = 1e-6f;
  float warnpercent = 0.0f;
  float hardfail = std::numeric_limits<float>::infinity();
  int shift = 0;
  bool linear = false;        // compare in linear light
  bool ignore_alpha = false;
  std::optional<double> ssim_min;
  std::optional<double> flip_max;
};

inline std::string results_directory() {
  const char* env = std::getenv("SPLINEFIG_TEST_RESULTS");
  return env && *env ? std::string(env) : std::string("build/test-results");
}

inline bool updating_references() {
  const char* env = std::getenv("SPLINEFIG_UPDATE_REFERENCES");
  return env && std::string(env) == "1";
}

namespace detail {

inline bool is_eight_bit_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& ch : ext) ch = char(std::tolower(ch));
  return ext != ".exr" && ext != ".hdr" && ext != ".tif" && ext != ".tiff";
}

// What the reference file would hold for `im`: a linear image against an 8-bit reference goes
// through the 8-bit sRGB file splinefig writes.
inline Image as_stored(const Image& im, const std::string& reference, bool linear) {
  if (!is_eight_bit_path(reference) || im.encoding != Encoding::linear) return im;
  namespace fs = std::filesystem;
  static int counter = 0;
  const fs::path tmp = fs::temp_directory_path() /
                       ("splinefig-match-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".png");
  write_image(tmp.string(), im);
  Image back = read_image(tmp.string(), linear ? ReadMode::linear : ReadMode::as_stored);
  std::error_code ec;
  fs::remove(tmp, ec);
  return back;
}

}  // namespace detail

class ReferenceMatcher : public Catch::MatcherBase<Image> {
 public:
  ReferenceMatcher(std::string reference, Tolerance tolerance)
      : m_reference(std::move(reference)), m_tolerance(tolerance) {}

  bool match(const Image& actual) const override {
    namespace fs = std::filesystem;
    if (updating_references()) {
      fs::create_directories(fs::path(m_reference).parent_path().empty() ? fs::path(".") : fs::path(m_reference).parent_path());
      write_image(m_reference, actual);
      m_message = "updated reference " + m_reference + " (SPLINEFIG_UPDATE_REFERENCES=1)";
      std::cerr << m_message << "\n";
      return true;
    }
    const std::string dir = results_directory();
    const fs::path ref(m_reference);
    const std::string stem = (fs::path(dir) / ref.stem()).string();
    const std::string ext = ref.extension().string();
    Image expected;
    try {
      expected = read_image(m_reference, m_tolerance.linear ? ReadMode::linear : ReadMode::as_stored);
    } catch (const UnreadableImage& e) {
      fs::create_directories(dir);
      write_image(stem + ".actual" + ext, actual);
      m_message = std::string("matches reference: cannot read it (") + e.what() +
                  "); run with SPLINEFIG_UPDATE_REFERENCES=1 to create it. Actual image: " + stem + ".actual" + ext;
      return false;
    }
    const Image stored = detail::as_stored(actual, m_reference, m_tolerance.linear);
    compare::Options o;
    o.thresholds.fail = m_tolerance.fail;
    o.thresholds.failpercent = m_tolerance.failpercent;
    o.thresholds.warn = m_tolerance.warn;
    o.thresholds.warnpercent = m_tolerance.warnpercent;
    o.thresholds.hardfail = m_tolerance.hardfail;
    o.shift = m_tolerance.shift;
    o.linear = m_tolerance.linear;
    o.ignore_alpha = m_tolerance.ignore_alpha;
    o.ssim_min = m_tolerance.ssim_min;
    o.flip_max = m_tolerance.flip_max;
    const compare::Comparison c = compare::compare_images(expected, stored, o);
    if (c.verdict != compare::Verdict::failure) {
      m_message = "matches reference " + m_reference;
      return true;
    }
    const float m = c.metrics.max_error;
    const float scale = m > 0.0f && std::isfinite(m) ? 1.0f / m : 1.0f;
    fs::create_directories(dir);
    write_image(stem + ".actual" + ext, actual);
    write_image(stem + ".diff.png", compare::difference_image(c.pa, c.pb, scale));
    write_image(stem + ".triptych.png", compare::triptych(c.pa, c.pb, scale));
    m_message = "matches reference " + m_reference + "\n" +
                compare::text_report(c, o, m_reference, "actual", true) +
                "  actual:   " + stem + ".actual" + ext + "\n" +
                "  diff:     " + stem + ".diff.png (x" + std::to_string(scale) + ")\n" +
                "  triptych: " + stem + ".triptych.png (expected | actual | difference)\n" +
                "  if the change is intended: SPLINEFIG_UPDATE_REFERENCES=1 and review the new reference";
    return false;
  }

  std::string describe() const override { return m_message.empty() ? "matches reference " + m_reference : m_message; }

 private:
  std::string m_reference;
  Tolerance m_tolerance;
  mutable std::string m_message;
};

inline ReferenceMatcher MatchesReference(std::string reference, Tolerance tolerance = {}) {
  return ReferenceMatcher(std::move(reference), tolerance);
}

}  // namespace splinefig::testing

namespace Catch {
template <>
struct StringMaker<splinefig::Image> {
  static std::string convert(const splinefig::Image& im) {
    return std::to_string(im.width) + " x " + std::to_string(im.height) + " image with " + std::to_string(im.channels) +
           " channels";
  }
};
}  // namespace Catch
