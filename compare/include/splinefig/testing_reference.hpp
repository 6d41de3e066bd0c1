#pragma once
// The comparison behind the image-test matchers: splinefig/testing.hpp (Catch2) and
// splinefig/testing_gtest.hpp (GoogleTest/GoogleMock) both call match_reference(), so the two
// share the options, the update mode and the artefacts. See testing.hpp for what it does.
#include <splinefig/compare/compare.hpp>
#include <splinefig/compare/report.hpp>
#include <splinefig/compare/visualize.hpp>
#include <splinefig/image/io.hpp>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
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

// The folder the references' artefact names are taken relative to: $SPLINEFIG_REFERENCE_ROOT,
// else SPLINEFIG_REFERENCE_ROOT_DIR if the test program defines it (e.g. its source directory),
// else none; absolute, or empty for none.
inline std::string reference_root() {
  namespace fs = std::filesystem;
  const char* env = std::getenv("SPLINEFIG_REFERENCE_ROOT");
  std::string root = env && *env ? std::string(env) : std::string();
#ifdef SPLINEFIG_REFERENCE_ROOT_DIR
  if (root.empty()) root = SPLINEFIG_REFERENCE_ROOT_DIR;
#endif
  if (root.empty()) return root;
  std::error_code ec;
  fs::path p = fs::absolute(fs::path(root), ec);
  p = (ec ? fs::path(root) : p).lexically_normal();
  if (p.has_relative_path() && p.filename().empty()) p = p.parent_path();  // a trailing '/'
  return p.string();
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

// The reference as an absolute path without . and .. parts.
inline std::string absolute_reference(const std::string& reference) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p = fs::absolute(fs::path(reference), ec);
  return (ec ? fs::path(reference) : p).lexically_normal().string();
}

// The artefacts' path without suffix: <results>/<test name>/<key>, where <key> is the
// reference's path relative to `root` without its extension when the reference is inside the
// root (tests/reference/figures/cbasis.png under tests/ gives reference/figures/cbasis), else its
// file stem. It depends on the reference file alone, never on the current directory. Two
// references outside the root with one stem, checked by one test, keep apart: the second is
// <stem>-2. Characters other than letters, digits and ._- become '_'.
inline std::string artefact_stem(const std::string& results, const std::string& test_name, const std::string& reference,
                                 const std::string& root) {
  namespace fs = std::filesystem;
  auto clean = [](std::string s) {
    for (auto& ch : s)
      if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '_' && ch != '-') ch = '_';
    return s == "." || s == ".." || s.empty() ? "_" + s : s;
  };
  const fs::path ref(absolute_reference(reference));
  fs::path out = fs::path(results);
  if (!test_name.empty()) out /= clean(test_name);
  fs::path rel;
  if (!root.empty()) rel = ref.lexically_relative(fs::path(root));
  if (!rel.empty() && *rel.begin() != ".." && rel.begin()->string() != ".") {
    for (const auto& part : rel.parent_path()) out /= clean(part.string());
    return (out / clean(rel.stem().string())).string();
  }
  // Outside the root: the stem, made unique among this process's references.
  static std::mutex lock;
  static std::map<std::string, std::string> owner;  // artefact stem -> the reference it is for
  const std::lock_guard<std::mutex> hold(lock);
  const std::string base = (out / clean(ref.stem().string())).string();
  for (int n = 1;; ++n) {
    const std::string stem = n == 1 ? base : base + "-" + std::to_string(n);
    auto [it, added] = owner.emplace(stem, ref.string());
    if (added || it->second == ref.string()) return stem;
  }
}

// Whether the alpha channels of the two images as compared hold any different value.
inline bool alpha_differs(const Image& a, const Image& b) {
  if (a.alpha_channel < 0 || b.alpha_channel < 0 || a.width != b.width || a.height != b.height) return false;
  const std::size_t n = std::size_t(a.width) * std::size_t(a.height);
  for (std::size_t i = 0; i < n; ++i) {
    const float va = a.pixels[i * std::size_t(a.channels) + std::size_t(a.alpha_channel)];
    const float vb = b.pixels[i * std::size_t(b.channels) + std::size_t(b.alpha_channel)];
    if (va != vb && !(std::isnan(va) && std::isnan(vb))) return true;
  }
  return false;
}

// The first line of a failure: the reference, the largest difference and where, the count over
// the fail threshold, and the failed perceptual checks.
inline std::string mismatch_line(const compare::Comparison& c, const compare::Options& o, const std::string& reference) {
  const compare::Metrics& m = c.metrics;
  std::string channel = std::to_string(m.max_c);
  if (m.max_c < int(c.a.channel_names.size())) channel = c.a.channel_names[std::size_t(m.max_c)];
  else if (m.max_c < int(c.b.channel_names.size())) channel = c.b.channel_names[std::size_t(m.max_c)];
  std::string s = std::string("does not match reference ") + reference + ": max error " + compare::format_g(m.max_error) +
                  " at pixel (" + std::to_string(m.max_x) + ", " + std::to_string(m.max_y) + ") channel " + channel +
                  ", " + std::to_string(m.nfail) + " of " + std::to_string(m.npels) + " pixels (" +
                  compare::format_percent(100.0 * double(m.nfail) / double(m.npels)) + "%) over fail " +
                  compare::format_shortest(o.thresholds.fail);
  if (c.sizes_differ) s += ", sizes differ";
  if (c.channels_differ) s += ", channel counts differ";
  for (const auto& f : c.failures) {
    s += "; ";
    s += f;
  }
  return s;
}

}  // namespace detail

// What match_reference() found: whether the image matches and the message to show.
struct Outcome {
  bool ok = false;
  std::string message;
};

// Compares `actual` with the reference file (or, with SPLINEFIG_UPDATE_REFERENCES=1, writes it
// as the new reference) and says what happened; on a failure the artefacts are written first,
// named after `test_name` (the running test's, may be empty) and the reference (artefact_stem):
// <stem>.actual.<ext>, <stem>.expected.<ext> (a copy of the reference), <stem>.diff.png,
// <stem>.alpha-diff.png (only when the alpha channels differ) and <stem>.triptych.png, replacing
// what an earlier failure left under that stem. The message of a failure begins "does not match
// reference" and gives the numbers and the artefacts' absolute paths.
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
  const std::string ref = detail::absolute_reference(reference);
  const std::string stem = detail::artefact_stem(results_directory(), test_name, reference, reference_root());
  const fs::path dir = fs::path(stem).parent_path();
  const std::string ext = fs::path(reference).extension().string();
  const std::string actual_file = stem + ".actual" + ext, expected_file = stem + ".expected" + ext;
  const std::string diff_file = stem + ".diff.png", alpha_file = stem + ".alpha-diff.png";
  const std::string triptych_file = stem + ".triptych.png";
  auto clear = [&] {
    std::error_code ec;
    for (const std::string* f : {&actual_file, &expected_file, &diff_file, &alpha_file, &triptych_file}) fs::remove(*f, ec);
    fs::create_directories(dir);
  };
  Image expected;
  try {
    expected = read_image(reference, tolerance.linear ? ReadMode::linear : ReadMode::as_stored);
  } catch (const UnreadableImage& e) {
    clear();
    write_image(actual_file, actual);
    const std::string message = std::string("does not match reference ") + ref + ": cannot read it (" + e.what() +
                                "); run with SPLINEFIG_UPDATE_REFERENCES=1 to create it\n"
                                "  actual:   " + actual_file + "\n";
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
    const std::string message = std::string("matches reference ") + ref;
    return {true, message};
  }
  const float m = c.metrics.max_error;
  const float scale = m > 0.0f && std::isfinite(m) ? 1.0f / m : 1.0f;
  const std::string times = std::string("x") + compare::format_g(scale);
  clear();
  write_image(actual_file, actual);
  fs::copy_file(fs::path(reference), fs::path(expected_file), fs::copy_options::overwrite_existing);
  write_image(diff_file, compare::difference_image(c.pa, c.pb, scale));
  write_image(triptych_file, compare::triptych(c.pa, c.pb, scale));
  const bool rgba = c.pa.alpha_channel >= 0 && c.pb.alpha_channel >= 0;
  const bool alpha = rgba && detail::alpha_differs(c.pa, c.pb);
  if (alpha) write_image(alpha_file, compare::alpha_difference_image(c.pa, c.pb, scale));
  const std::string message = detail::mismatch_line(c, o, ref) + "\n" +
              compare::text_report(c, o, ref, actual_file, true) +
              "  actual:   " + actual_file + "\n" +
              "  expected: " + expected_file + " (a copy of the reference)\n" +
              "  diff:     " + diff_file + " (" + times + (rgba ? ", colour channels" : "") + ")\n" +
              (alpha ? std::string("  alpha:    ") + alpha_file + " (" + times + ")\n"
                     : rgba ? "  alpha:    the same in both (no alpha-diff.png)\n" : std::string()) +
              "  triptych: " + triptych_file + " (expected | actual | difference)\n" +
              "  if the change is intended: SPLINEFIG_UPDATE_REFERENCES=1 and review the new reference";
  return {false, message};
}

}  // namespace splinefig::testing
