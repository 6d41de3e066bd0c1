// EXPECT_THAT(render_spec_to_image("fig.toml"), MatchesReference("fig.png")): a spec checked
// against a reference in one line with GoogleTest, as with Catch2 (tests/figures/render_spec.cpp).
#include <splinefig/figures/figure.hpp>
#include <splinefig/testing_gtest.hpp>

#include <gtest/gtest-spi.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using splinefig::figures::render_spec_to_image;
using splinefig::testing::gmock::MatchesReference;

namespace {

const std::string kCbasis = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/cbasis.toml";
const std::string kReference = std::string(SPLINEFIG_SOURCE_DIR) + "/tests/reference/figures/cbasis.png";

// The suite's figure tolerance (tests/reference_check.hpp).
splinefig::testing::Tolerance figure() {
  splinefig::testing::Tolerance t;
  t.fail = 2.5f / 255;
  t.warn = 1.5f / 255;
  t.failpercent = 0.01f;
  t.warnpercent = 0.01f;
  return t;
}

}  // namespace

TEST(MatchesReferenceOnASpec, TheBuiltInFigureMatchesItsReference) {
  EXPECT_THAT(render_spec_to_image(kCbasis), MatchesReference(kReference, figure()));
}

TEST(MatchesReferenceOnASpec, AChangedSpecFails) {
  const fs::path dir = fs::path(SPLINEFIG_BINARY_DIR) / "test-scratch" / "gtest-spec";
  fs::create_directories(dir);
  std::ifstream in(kCbasis);
  std::ostringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  const auto orange = text.find("\"#e69f00\"");  // the second half's colour
  ASSERT_NE(orange, std::string::npos);
  text.replace(orange, 9, "\"#2ca02c\"");
  { std::ofstream(dir / "green.toml") << text; }
  ::setenv("SPLINEFIG_TEST_RESULTS", (dir / "results").c_str(), 1);
  EXPECT_NONFATAL_FAILURE(
      EXPECT_THAT(render_spec_to_image((dir / "green.toml").string()), MatchesReference(kReference, figure())),
      (dir / "results").string());
  ::unsetenv("SPLINEFIG_TEST_RESULTS");
}
