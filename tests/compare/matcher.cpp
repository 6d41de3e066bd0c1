// splinefig/testing.hpp: MatchesReference in update mode, on a match, and on a mismatch (with
// the actual, diff and triptych images written to the results directory).
#include "support.hpp"

#include <splinefig/image/srgb.hpp>
#include <splinefig/testing.hpp>

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>

using namespace splinefig;
using namespace splinefig::compare;
using splinefig::testing::MatchesReference;

namespace {
// The renderer's form: linear RGBA, associated alpha.
Image linear_rgba(int w, int h, const float* rgba) {
  Image im(w, h, 4);
  std::copy(rgba, rgba + im.pixels.size(), im.pixels.begin());
  return im;
}
}  // namespace
using test_support::scratch;
namespace fs = std::filesystem;

namespace {

// A linear premultiplied RGBA image as the renderer makes them: a soft disc over transparency.
std::vector<float> disc_rgba(int w, int h, float red) {
  std::vector<float> px(std::size_t(w * h * 4), 0.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double d = std::hypot(x + 0.5 - w / 2.0, y + 0.5 - h / 2.0);
      const float a = float(std::clamp(w / 3.0 - d + 0.5, 0.0, 1.0));
      float* p = &px[std::size_t((y * w + x) * 4)];
      p[0] = red * a;
      p[1] = 0.25f * a;
      p[2] = 0.05f * a;
      p[3] = a;
    }
  return px;
}

struct Env {
  Env(const char* name, const std::string& value) : name(name) { setenv(name, value.c_str(), 1); }
  ~Env() { unsetenv(name); }
  const char* name;
};

}  // namespace

TEST_CASE("MatchesReference: update mode writes the reference, then the same image matches") {
  const std::string results = scratch("matcher-results");
  fs::remove_all(results);
  const Env env_results("SPLINEFIG_TEST_RESULTS", results);
  const std::string ref = scratch("matcher-disc.png");
  fs::remove(ref);
  const auto px = disc_rgba(24, 20, 0.8f);
  const Image img = linear_rgba(24, 20, px.data());
  {
    const Env update("SPLINEFIG_UPDATE_REFERENCES", "1");
    auto m = MatchesReference(ref);
    CHECK(m.match(img));
    CHECK(m.describe().find("updated reference " + ref) != std::string::npos);
  }
  REQUIRE(fs::exists(ref));
  // The reference is 8-bit sRGB with straight alpha: the disc's centre is red 0.8 linear.
  const Image back = read_image(ref);
  CHECK(back.channels == 4);
  CHECK(back.at(12, 10, 0) == Approx(std::lround(linear_to_srgb(0.8f) * 255.0f) / 255.0).epsilon(1e-6));
  CHECK_THAT(img, MatchesReference(ref));
  CHECK_FALSE(fs::exists(results));  // nothing written on success
}

TEST_CASE("MatchesReference: a mismatch writes actual, diff and triptych and reports them") {
  const std::string results = scratch("matcher-results");
  fs::remove_all(results);
  const Env env_results("SPLINEFIG_TEST_RESULTS", results);
  const std::string ref = scratch("matcher-disc2.png");
  const auto px = disc_rgba(24, 20, 0.8f), other = disc_rgba(24, 20, 0.3f);
  {
    const Env update("SPLINEFIG_UPDATE_REFERENCES", "1");
    CHECK(MatchesReference(ref).match(linear_rgba(24, 20, px.data())));
  }
  auto m = MatchesReference(ref, {.fail = 0.01f});
  CHECK_FALSE(m.match(linear_rgba(24, 20, other.data())));
  const std::string msg = m.describe();
  CHECK(msg.find("  Mean error = ") != std::string::npos);
  CHECK(msg.find("FAILURE") != std::string::npos);
  for (const char* f : {"matcher-disc2.actual.png", "matcher-disc2.diff.png", "matcher-disc2.triptych.png"}) {
    CHECK(fs::exists(fs::path(results) / f));
    CHECK(msg.find((fs::path(results) / f).string()) != std::string::npos);
  }
  const Image trip = read_image((fs::path(results) / "matcher-disc2.triptych.png").string());
  CHECK(trip.width == 3 * 24 + 4);
  // Within a generous tolerance the same pair matches.
  CHECK_THAT(linear_rgba(24, 20, other.data()), MatchesReference(ref, {.fail = 0.5f}));
}

TEST_CASE("MatchesReference: a missing reference fails and says how to create it") {
  const Env env_results("SPLINEFIG_TEST_RESULTS", scratch("matcher-results"));
  const auto px = disc_rgba(8, 8, 0.5f);
  auto m = MatchesReference(scratch("no-such-reference.png"));
  CHECK_FALSE(m.match(linear_rgba(8, 8, px.data())));
  CHECK(m.describe().find("SPLINEFIG_UPDATE_REFERENCES=1") != std::string::npos);
}

TEST_CASE("MatchesReference: EXR references hold the linear floats") {
  const Env env_results("SPLINEFIG_TEST_RESULTS", scratch("matcher-results"));
  const std::string ref = scratch("matcher-disc.exr");
  const auto px = disc_rgba(16, 16, 0.8f);
  const Image img = linear_rgba(16, 16, px.data());
  {
    const Env update("SPLINEFIG_UPDATE_REFERENCES", "1");
    CHECK(MatchesReference(ref).match(img));
  }
  const Image back = read_image(ref);
  CHECK(back.pixels == img.pixels);
  CHECK_THAT(img, MatchesReference(ref));
}

TEST_CASE("MatchesReference: only SPLINEFIG_UPDATE_REFERENCES=1 rewrites a reference") {
  // Every reference check of the suite goes through this matcher (tests/reference_check.hpp),
  // so "0", an empty value or any other word must compare, fail on a mismatch and leave the file.
  const Env env_results("SPLINEFIG_TEST_RESULTS", scratch("matcher-results"));
  const std::string ref = scratch("matcher-disc3.png");
  const auto px = disc_rgba(24, 20, 0.8f), other = disc_rgba(24, 20, 0.3f);
  {
    const Env update("SPLINEFIG_UPDATE_REFERENCES", "1");
    CHECK(MatchesReference(ref).match(linear_rgba(24, 20, px.data())));
  }
  const auto before = fs::last_write_time(ref);
  const Image kept = read_image(ref);
  for (const char* value : {"0", "", "no", "true"}) {
    INFO("SPLINEFIG_UPDATE_REFERENCES=" << value);
    const Env update("SPLINEFIG_UPDATE_REFERENCES", value);
    CHECK_FALSE(MatchesReference(ref, {.fail = 0.01f}).match(linear_rgba(24, 20, other.data())));
    CHECK(fs::last_write_time(ref) == before);
    CHECK(read_image(ref).pixels == kept.pixels);
  }
}
