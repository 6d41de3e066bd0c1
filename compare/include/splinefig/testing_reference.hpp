#pragma once
// The comparison behind the image-test matchers: splinefig/testing.hpp (Catch2) and
// splinefig/testing_gtest.hpp (GoogleTest/GoogleMock) both call match_reference(), so the two
// share the options, the update mode and the artefacts. See testing.hpp for what it does.
#include <splinefig/compare/compare.hpp>
#include <splinefig/compare/visualize.hpp>
#include <splinefig/image/io.hpp>

#include <cctype>
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
  std::optional<double> ssim_min{};
  std::optional<double> flip_max{};
};

// Where a failed match writes its artefacts: $SPLINEFIG_TEST_RESULTS, else test-results/ in the
// build directory of the test program (SPLINEFIG_TEST_RESULTS_DIR, which the splinefig::testing
// targets define), else test-results/ in the current directory; always absolute.
inline std::string results_directory() {
  namespace fs = std::filesystem;
  const char* env = std::getenv("SPLINEFIG_TEST_RESULTS");
#ifdef SPLINEFIG_TEST_RESULTS_DIR
  const fs::path dir = env && *env ? fs::path(env) : fs::path(SPLINEFIG_TEST_RESULTS_DIR);
#else
  const fs::path dir = env && *env ? fs::path(env) : fs::path("test-results");
#endif
  std::error_code ec;
  const fs::path absolute = fs::absolute(dir, ec);
  return (ec ? dir : absolute).lexically_normal().string();
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

// The artefacts' path without suffix: <results>/<test name>/<reference path>, the reference path
// relative to the current directory when it is inside it (else absolute), without its extension,
// so that references of the same name in different folders, or one reference checked by several
// tests, keep apart. Characters other than letters, digits and ._- become '_'.
inline std::string artefact_stem(const std::string& results, const std::string& test_name, const std::string& reference) {
  namespace fs = std::filesystem;
  auto clean = [](std::string s) {
    for (auto& ch : s)
      if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '_' && ch != '-') ch = '_';
    return s == "." || s == ".." || s.empty() ? "_" + s : s;
  };
  std::error_code ec;
  fs::path ref = fs::absolute(fs::path(reference), ec).lexically_normal();
  const fs::path cwd = fs::current_path(ec);
  if (!ec) {
    const fs::path rel = ref.lexically_relative(cwd);
    if (!rel.empty() && *rel.begin() != "..") ref = rel;
  }
  fs::path out = fs::path(results);
  if (!test_name.empty()) out /= clean(test_name);
  const fs::path parent = ref.parent_path();
  for (const auto& part : parent.relative_path()) out /= clean(part.string());
  out /= clean(ref.stem().string());
  return out.string();
}

}  // namespace detail

// What match_reference() found: whether the image matches and the message to show.
struct Outcome {
  bool ok = false;
  std::string message;
};

// Compares `actual` with the reference file (or, with SPLINEFIG_UPDATE_REFERENCES=1, writes it
// as the new reference) and says what happened; on a failure the artefacts are written first,
// named after `test_name` (the running test's, may be empty) and the reference's path.
inline Outcome match_reference(const Image& actual, const std::string& reference, const Tolerance& tolerance,
                               const std::string& test_name = {}) {
  namespace fs = std::filesystem;
  if (updating_references()) {
    fs::create_directories(fs::path(reference).parent_path().empty() ? fs::path(".") : fs::path(reference).parent_path());
    write_image(reference, actual);
    const std::string message = "updated reference " + reference + " (SPLINEFIG_UPDATE_REFERENCES=1)";
    std::cerr << message << "\n";
    return {true, message};
  }
  const fs::path ref(reference);
  const std::string stem = detail::artefact_stem(results_directory(), test_name, reference);
  const fs::path dir = fs::path(stem).parent_path();
  const std::string ext = ref.extension().string();
  Image expected;
  try {
    expected = read_image(reference, tolerance.linear ? ReadMode::linear : ReadMode::as_stored);
  } catch (const UnreadableImage& e) {
    fs::create_directories(dir);
    write_image(stem + ".actual" + ext, actual);
    const std::string message = std::string("matches reference: cannot read it (") + e.what() +
                "); run with SPLINEFIG_UPDATE_REFERENCES=1 to create it. Actual image: " + stem + ".actual" + ext;
    return {false, message};
  }
  const Image stored = detail::as_stored(actual, reference, tolerance.linear);
  compare::Options o;
  o.thresholds.fail = tolerance.fail;
  o.thresholds.failpercent = tolerance.failpercent;
  o.thresholds.warn = tolerance.warn;
  o.thresholds.warnpercent = tolerance.warnpercent;
  o.thresholds.hardfail = tolerance.hardfail;
  o.shift = tolerance.shift;
  o.linear = tolerance.linear;
  o.ignore_alpha = tolerance.ignore_alpha;
  o.ssim_min = tolerance.ssim_min;
  o.flip_max = tolerance.flip_max;
  const compare::Comparison c = compare::compare_images(expected, stored, o);
  if (c.verdict != compare::Verdict::failure) {
    const std::string message = "matches reference " + reference;
    return {true, message};
  }
  const float m = c.metrics.max_error;
  const float scale = m > 0.0f && std::isfinite(m) ? 1.0f / m : 1.0f;
  fs::create_directories(dir);
  write_image(stem + ".actual" + ext, actual);
  write_image(stem + ".diff.png", compare::difference_image(c.pa, c.pb, scale));
  write_image(stem + ".triptych.png", compare::triptych(c.pa, c.pb, scale));
  const bool alpha = c.pa.alpha_channel >= 0 && c.pb.alpha_channel >= 0;
  if (alpha) write_image(stem + ".alpha-diff.png", compare::alpha_difference_image(c.pa, c.pb, scale));
  const std::string message = "matches reference " + reference + "\n" +
              compare::text_report(c, o, reference, "actual", true) +
              "  actual:   " + stem + ".actual" + ext + "\n" +
              "  diff:     " + stem + ".diff.png (x" + std::to_string(scale) + (alpha ? ", colour" : "") + ")\n" +
              (alpha ? "  alpha:    " + stem + ".alpha-diff.png (x" + std::to_string(scale) + ")\n" : std::string()) +
              "  triptych: " + stem + ".triptych.png (expected | actual | difference)\n" +
              "  if the change is intended: SPLINEFIG_UPDATE_REFERENCES=1 and review the new reference";
  return {false, message};
}

}  // namespace splinefig::testing
