#pragma once
// Catch2 support for image tests (v2, and v3 where its headers are present): compare a
// rendered image with a reference file.
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
// On failure the matcher writes <stem>.actual.<ext>, <stem>.expected.<ext> (a copy of the
// reference), <stem>.diff.png (|a-b| scaled so the largest difference is 1; for RGBA the colour
// channels), <stem>.alpha-diff.png (the alpha channel's, only when alpha differs) and
// <stem>.triptych.png (expected | actual | heat map), replacing what an earlier failure left
// there. <stem> is <results>/<test name>/<key>: <results> is $SPLINEFIG_TEST_RESULTS or else
// test-results/ in the test's build directory (absolute); <key> is the reference's path
// relative to $SPLINEFIG_REFERENCE_ROOT (or SPLINEFIG_REFERENCE_ROOT_DIR) without its extension
// when it lies inside, else the reference's file stem: never the current directory's. The
// message begins "does not match reference <absolute path>: max error E at pixel (x, y) channel
// C, N of M pixels (P%) over fail F", then idiff's report and the files' absolute paths. With
// SPLINEFIG_UPDATE_REFERENCES=1 it writes the image as the new reference instead, says so, and
// passes: review the change (git diff, the images) before committing.
//
// Header-only on purpose: only test code includes it, and it needs Catch2's headers (the
// splinefig::testing CMake target brings them and splinefig::compare). The same matcher for
// GoogleTest/GoogleMock is in splinefig/testing_gtest.hpp.
#include <splinefig/testing_reference.hpp>

// Catch2 v3's headers where they are present, else Catch2 v2's single header (Debian 12's).
#if __has_include(<catch2/catch_test_macros.hpp>)
#include <catch2/catch_test_macros.hpp>
#include <catch2/catch_tostring.hpp>
#include <catch2/interfaces/catch_interfaces_capture.hpp>
#include <catch2/matchers/catch_matchers.hpp>
#define SPLINEFIG_CATCH_MATCHER_BASE Catch::Matchers::MatcherBase
#else
#include <catch2/catch.hpp>
#define SPLINEFIG_CATCH_MATCHER_BASE Catch::MatcherBase
#endif

#include <iostream>
#include <string>

namespace splinefig::testing {

class ReferenceMatcher : public SPLINEFIG_CATCH_MATCHER_BASE<Image> {
 public:
  ReferenceMatcher(std::string reference, Tolerance tolerance)
      : m_reference(std::move(reference)), m_tolerance(tolerance) {}

  bool match(const Image& actual) const override {
    Outcome o = match_reference(actual, m_reference, m_tolerance, Catch::getResultCapture().getCurrentTestName());
    m_message = std::move(o.message);
    return o.ok;
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
