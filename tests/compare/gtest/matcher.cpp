// splinefig/testing_gtest.hpp: EXPECT_THAT(img, MatchesReference(...)) in update mode, on a
// match, and on a mismatch (the actual, diff and triptych images written, their paths in the
// message). The images are chosen so that their 8-bit files are known without splinefig:
// linear 1 and 0 are sRGB 255 and 0.
#include <splinefig/testing_gtest.hpp>

#include <gtest/gtest-spi.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using splinefig::Image;
using splinefig::testing::gmock::MatchesReference;

namespace {

// Linear premultiplied RGBA, as the renderer makes them: the columns left of `edge` opaque
// white, the rest transparent.
Image half_white(int edge) {
  Image im = Image::zeros(8, 6, 4);
  for (int j = 0; j < im.height; ++j)
    for (int i = 0; i < edge; ++i)
      for (int c = 0; c < 4; ++c) im.at(i, j, c) = 1.0f;
  return im;
}

struct Env {
  Env(const char* name, const std::string& value) : name(name) { setenv(name, value.c_str(), 1); }
  ~Env() { unsetenv(name); }
  const char* name;
};

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(SPLINEFIG_BINARY_DIR) / "test-scratch" / "gtest";
  fs::create_directories(dir);
  return dir / name;
}

}  // namespace

TEST(MatchesReference, UpdateModeWritesTheReferenceThenTheSameImageMatches) {
  const fs::path results = scratch("results-update");
  fs::remove_all(results);
  const Env env_results("SPLINEFIG_TEST_RESULTS", results.string());
  const std::string ref = scratch("half.png").string();
  fs::remove(ref);
  {
    const Env update("SPLINEFIG_UPDATE_REFERENCES", "1");
    EXPECT_THAT(half_white(4), MatchesReference(ref));
  }
  ASSERT_TRUE(fs::exists(ref));
  const Image back = splinefig::read_image(ref);
  ASSERT_EQ(back.channels, 4);
  EXPECT_EQ(back.at(1, 1, 0), 1.0f);
  EXPECT_EQ(back.at(1, 1, 3), 1.0f);
  EXPECT_EQ(back.at(6, 1, 3), 0.0f);
  EXPECT_THAT(half_white(4), MatchesReference(ref));
  EXPECT_FALSE(fs::exists(results));  // nothing written on success
}

TEST(MatchesReference, AMismatchFailsAndWritesActualDiffAndTriptych) {
  const fs::path results = scratch("results-mismatch");
  fs::remove_all(results);
  const Env env_results("SPLINEFIG_TEST_RESULTS", results.string());
  const std::string ref = scratch("half-mismatch.png").string();
  {
    const Env update("SPLINEFIG_UPDATE_REFERENCES", "1");
    EXPECT_THAT(half_white(4), MatchesReference(ref));
  }
  EXPECT_NONFATAL_FAILURE(EXPECT_THAT(half_white(5), MatchesReference(ref)), "triptych: ");
  EXPECT_THAT(half_white(5), ::testing::Not(MatchesReference(ref)));
  std::size_t written = 0;
  for (const auto& e : fs::recursive_directory_iterator(results)) {
    const std::string name = e.path().filename().string();
    for (const char* suffix : {".actual.png", ".diff.png", ".triptych.png"})
      if (name.size() > std::string(suffix).size() && name.ends_with(suffix)) ++written;
  }
  EXPECT_EQ(written, 3u);
  // One column of 6 pixels differs: the message gives the idiff numbers.
  const ::testing::Matcher<const Image&> m = MatchesReference(ref);
  ::testing::StringMatchResultListener listener;
  EXPECT_FALSE(m.MatchAndExplain(half_white(5), &listener));
  EXPECT_NE(listener.str().find("6 pixels (12.5%) over 1e-06"), std::string::npos) << listener.str();
  EXPECT_NE(listener.str().find("FAILURE"), std::string::npos);
}

TEST(MatchesReference, AMissingReferenceFailsAndSaysHowToCreateIt) {
  const Env env_results("SPLINEFIG_TEST_RESULTS", scratch("results-missing").string());
  EXPECT_NONFATAL_FAILURE(EXPECT_THAT(half_white(4), MatchesReference(scratch("no-such.png").string())),
                          "SPLINEFIG_UPDATE_REFERENCES=1");
}
