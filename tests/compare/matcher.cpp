// splinefig/testing.hpp: MatchesReference in update mode, on a match, and on a mismatch (with
// the actual, expected, diff and triptych images written to the results directory, and the
// alpha diff only when alpha differs).
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

// The path the failure message gives after `label` ("actual:", "diff:", ...).
std::string artefact(const std::string& message, const std::string& label) {
  const auto at = message.find("  " + label);
  if (at == std::string::npos) return {};
  auto begin = message.find_first_not_of(' ', at + 2 + label.size());
  auto end = message.find_first_of(" \n", begin);
  return message.substr(begin, end - begin);
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
  INFO(msg);
  // What Catch2 prints after the image: that it does not match, and by how much.
  CHECK(msg.rfind(std::string("does not match reference ") + ref + ": max error ", 0) == 0);
  CHECK(msg.find("  Mean error = ") != std::string::npos);
  CHECK(msg.find("FAILURE") != std::string::npos);
  for (const char* label : {"actual:", "expected:", "diff:", "triptych:"}) {
    INFO(label << " in " << msg);
    const std::string path = artefact(msg, label);
    CHECK(fs::path(path).is_absolute());
    CHECK(path.rfind(results + "/", 0) == 0);
    CHECK(fs::exists(path));
  }
  // The two discs have the same coverage: no alpha difference to show, so no alpha-diff.png.
  CHECK(msg.find("  alpha:    the same in both") != std::string::npos);
  const std::string actual = artefact(msg, "actual:");
  REQUIRE(actual.ends_with(".actual.png"));
  CHECK(fs::exists(actual));
  CHECK_FALSE(fs::exists(actual.substr(0, actual.size() - 11) + ".alpha-diff.png"));
  const Image trip = read_image(artefact(msg, "triptych:"));
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

TEST_CASE("MatchesReference: artefacts of references with the same file name in different folders keep apart") {
  const std::string results = scratch("matcher-results-apart");
  fs::remove_all(results);
  const Env env_results("SPLINEFIG_TEST_RESULTS", results);
  const std::string ref_a = scratch("apart-a/disc.png"), ref_b = scratch("apart-b/disc.png");
  const auto px = disc_rgba(24, 20, 0.8f), a = disc_rgba(24, 20, 0.5f), b = disc_rgba(24, 20, 0.1f);
  {
    const Env update("SPLINEFIG_UPDATE_REFERENCES", "1");
    CHECK(MatchesReference(ref_a).match(linear_rgba(24, 20, px.data())));
    CHECK(MatchesReference(ref_b).match(linear_rgba(24, 20, px.data())));
  }
  auto ma = MatchesReference(ref_a);
  auto mb = MatchesReference(ref_b);
  CHECK_FALSE(ma.match(linear_rgba(24, 20, a.data())));
  CHECK_FALSE(mb.match(linear_rgba(24, 20, b.data())));
  const std::string actual_a = artefact(ma.describe(), "actual:"), actual_b = artefact(mb.describe(), "actual:");
  CHECK(actual_a != actual_b);
  // Each actual image is the one its own check saw (red 0.5 and 0.1 at the centre).
  CHECK(read_image(actual_a, ReadMode::linear).at(12, 10, 0) == Approx(0.5).margin(0.01));
  CHECK(read_image(actual_b, ReadMode::linear).at(12, 10, 0) == Approx(0.1).margin(0.01));
  // The test's name is part of the path, so two tests checking one reference keep apart too.
  CHECK(actual_a.find("MatchesReference__artefacts_of_references") != std::string::npos);
}

TEST_CASE("MatchesReference: without SPLINEFIG_TEST_RESULTS artefacts go to an absolute directory") {
  const char* was = std::getenv("SPLINEFIG_TEST_RESULTS");
  const std::string saved = was ? was : "";
  unsetenv("SPLINEFIG_TEST_RESULTS");
  const std::string dir = splinefig::testing::results_directory();
  if (!saved.empty()) setenv("SPLINEFIG_TEST_RESULTS", saved.c_str(), 1);
  CHECK(fs::path(dir).is_absolute());
  // splinefig::testing points it at test-results/ in the build directory of this test program.
  CHECK(dir == (fs::path(SPLINEFIG_BINARY_DIR) / "tests" / "test-results").lexically_normal().string());
}

TEST_CASE("MatchesReference: the diff image of an RGBA render shows the colour difference") {
  // Two discs of the same coverage and different red: the alpha channels agree, so a diff
  // stored with |alpha difference| as its alpha would be invisible (all 0 when read back).
  const std::string results = scratch("matcher-results-rgba");
  fs::remove_all(results);
  const Env env_results("SPLINEFIG_TEST_RESULTS", results);
  const std::string ref = scratch("matcher-rgba.png");
  const auto px = disc_rgba(24, 20, 0.8f), other = disc_rgba(24, 20, 0.3f);
  {
    const Env update("SPLINEFIG_UPDATE_REFERENCES", "1");
    CHECK(MatchesReference(ref).match(linear_rgba(24, 20, px.data())));
  }
  auto m = MatchesReference(ref);
  CHECK_FALSE(m.match(linear_rgba(24, 20, other.data())));
  const Image diff = read_image(artefact(m.describe(), "diff:"));
  REQUIRE(diff.width == 24);
  // The largest difference, red at the disc's centre, is scaled to 1; green and blue agree.
  CHECK(diff.at(12, 10, 0) == Approx(1.0).margin(1e-6));
  CHECK(diff.at(12, 10, 1) == 0.0f);
  CHECK(diff.at(0, 0, 0) == 0.0f);  // transparent in both
  // Same coverage: no alpha-diff.png (it would be all 0), and the message says why.
  const std::string diff_file = artefact(m.describe(), "diff:");
  REQUIRE(diff_file.ends_with(".diff.png"));
  const std::string stem = diff_file.substr(0, diff_file.size() - 9);
  CHECK_FALSE(fs::exists(stem + ".alpha-diff.png"));
  CHECK(m.describe().find("  alpha:    the same in both") != std::string::npos);
}
