#pragma once
// GoogleTest/GoogleMock support for image tests: the matcher of splinefig/testing.hpp, with the
// same Tolerance, update mode (SPLINEFIG_UPDATE_REFERENCES=1) and artefacts.
//
//   #include <splinefig/testing_gtest.hpp>
//   using splinefig::testing::gmock::MatchesReference;
//   splinefig::Image img = ...;  // e.g. splinefig::render::rasterize(scene)
//   EXPECT_THAT(img, MatchesReference("tests/reference/cbasis.png", {.fail = 2.0f / 255, .shift = 1}));
//
// Header-only: link splinefig::compare and GTest::gmock (the splinefig::testing_gtest CMake
// target brings both).
#include <splinefig/testing_reference.hpp>

#include <gmock/gmock.h>

#include <ostream>
#include <string>

namespace splinefig {
// How GoogleTest prints an image in a failure message.
inline void PrintTo(const Image& im, std::ostream* os) {
  *os << im.width << " x " << im.height << " image with " << im.channels << " channels";
}
}  // namespace splinefig

namespace splinefig::testing::gmock {

class ReferenceMatcher : public ::testing::MatcherInterface<const Image&> {
 public:
  ReferenceMatcher(std::string reference, Tolerance tolerance)
      : m_reference(std::move(reference)), m_tolerance(tolerance) {}

  bool MatchAndExplain(const Image& actual, ::testing::MatchResultListener* listener) const override {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name = test ? std::string(test->test_suite_name()) + "." + test->name() : std::string();
    const Outcome o = match_reference(actual, m_reference, m_tolerance, name);
    *listener << o.message;
    return o.ok;
  }
  void DescribeTo(std::ostream* os) const override { *os << "matches reference " << m_reference; }
  void DescribeNegationTo(std::ostream* os) const override { *os << "does not match reference " << m_reference; }

 private:
  std::string m_reference;
  Tolerance m_tolerance;
};

inline ::testing::Matcher<const Image&> MatchesReference(std::string reference, Tolerance tolerance = {}) {
  return ::testing::MakeMatcher(new ReferenceMatcher(std::move(reference), tolerance));
}

}  // namespace splinefig::testing::gmock
