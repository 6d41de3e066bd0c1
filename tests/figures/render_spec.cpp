// A spec checked against a reference in one line, as users write such tests:
//   CHECK_THAT(render_spec_to_image("fig.toml"), MatchesReference("fig.png"));
// It matches the built-in figure's reference, it fails on a spec drawn in another colour with
// the artefacts at absolute paths named after the test case, and a bad spec throws one line.
#include "reference_check.hpp"

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/testing.hpp>

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;
using splinefig::figures::render_spec_to_image;
using splinefig::testing::MatchesReference;

namespace {

const std::string kCbasis = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/cbasis.toml";

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("render_spec_to_image: a spec against its reference in one line") {
  CHECK_THAT(render_spec_to_image(kCbasis), MatchesReference(reference_check::path("figures/cbasis.png"),
                                                             reference_check::figure()));
  const splinefig::Image twice = render_spec_to_image(kCbasis, {2, 1});
  CHECK(twice.width == 1600);
  CHECK(twice.height == 1000);
}

TEST_CASE("render_spec_to_image: a changed spec fails with its artefacts at absolute paths") {
  const fs::path dir = fs::temp_directory_path() / ("splinefig-render-spec-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string text = read_text(kCbasis);
  const auto red = text.find("\"#e69f00\"");
  REQUIRE(red != std::string::npos);
  text.replace(red, 9, "\"#2ca02c\"");
  { std::ofstream(dir / "green.toml") << text; }
  ::setenv("SPLINEFIG_TEST_RESULTS", (dir / "results").c_str(), 1);
  auto matcher = MatchesReference(reference_check::path("figures/cbasis.png"), reference_check::figure());
  CHECK_FALSE(matcher.match(render_spec_to_image((dir / "green.toml").string())));
  const std::string message = matcher.describe();
  INFO(message);
  CHECK_THAT(message, Catch::Contains("FAILURE"));
  CHECK_THAT(message, Catch::Contains((dir / "results").string()));
  bool diff_written = false;
  for (const auto& e : fs::recursive_directory_iterator(dir / "results"))
    diff_written = diff_written || e.path().string().ends_with("cbasis.diff.png");
  CHECK(diff_written);
  ::unsetenv("SPLINEFIG_TEST_RESULTS");
  fs::remove_all(dir);
}

TEST_CASE("render_spec_to_image: a missing or bad spec throws one line naming it") {
  CHECK_THROWS_WITH(render_spec_to_image("no/such.toml"), "no/such.toml: cannot read the spec file (No such file or directory)");
  const fs::path bad = fs::temp_directory_path() / ("splinefig-bad-spec-" + std::to_string(::getpid()) + ".toml");
  { std::ofstream(bad) << "[canvas]\nwidth = \"wide\"\n"; }
  CHECK_THROWS_AS(render_spec_to_image(bad.string()), splinefig::figures::SpecFileError);
  CHECK_THROWS_WITH(render_spec_to_image(bad.string()), Catch::StartsWith(bad.string() + ":2: canvas.width"));
  fs::remove(bad);
}
