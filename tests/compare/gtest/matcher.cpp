// splinefig/testing_gtest.hpp: EXPECT_THAT(img, MatchesReference(...)) in update mode, on a
// match, and on a mismatch (the actual, diff and triptych images written, their paths in the
// message). The images are chosen so that their 8-bit files are known without splinefig:
// linear 1 and 0 are sRGB 255 and 0.
#include <splinefig/testing_gtest.hpp>

#include <gtest/gtest-spi.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

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

// The path the failure message gives after `label` ("actual:", "diff:", ...), or "".
std::string artefact(const std::string& message, const std::string& label) {
  const auto at = message.find(std::string("\n  ") + label);
  if (at == std::string::npos) return {};
  const auto begin = message.find_first_not_of(' ', at + 3 + label.size());
  const auto end = message.find_first_of(" \n", begin);
  return message.substr(begin, end - begin);
}

// The matcher's explanation of `actual` against `ref` (what EXPECT_THAT prints after "Actual:").
std::string explain(const Image& actual, const std::string& ref, bool* matched = nullptr) {
  ::testing::StringMatchResultListener listener;
  const bool ok = ::testing::ExplainMatchResult(MatchesReference(ref), actual, &listener);
  if (matched) *matched = ok;
  return listener.str();
}

std::string this_test() {
  const auto* t = ::testing::UnitTest::GetInstance()->current_test_info();
  return std::string(t->test_suite_name()) + "." + t->name();
}

// Runs in another working directory, and comes back.
struct InDirectory {
  explicit InDirectory(const fs::path& dir) : was(fs::current_path()) { fs::current_path(dir); }
  ~InDirectory() { fs::current_path(was); }
  fs::path was;
};

// half_white(edge) with its opaque columns grey (linear 0.5): the same alpha, other colour.
Image half_grey(int edge) {
  Image im = half_white(edge);
  for (int j = 0; j < im.height; ++j)
    for (int i = 0; i < edge; ++i)
      for (int c = 0; c < 3; ++c) im.at(i, j, c) = 0.5f;
  return im;
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
  const std::string text = explain(half_white(4), scratch("no-such.png").string());
  const std::string start = std::string("does not match reference ") + scratch("no-such.png").string() + ": cannot read it";
  EXPECT_EQ(text.rfind(start, 0), 0u) << text;
  EXPECT_TRUE(fs::is_regular_file(artefact(text, "actual:"))) << text;
}

TEST(MatchesReference, AMismatchSaysItDoesNotMatchWithTheNumbersAndTheAbsolutePaths) {
  const fs::path results = scratch("results-text");
  fs::remove_all(results);
  const Env env_results("SPLINEFIG_TEST_RESULTS", results.string());
  const std::string ref = scratch("half-text.png").string();
  {
    const Env update("SPLINEFIG_UPDATE_REFERENCES", "1");
    EXPECT_THAT(half_white(4), MatchesReference(ref));
  }
  // Column 4 (6 of the 8 x 6 pixels) is transparent black in the reference and opaque white in
  // the image: every channel is off by 1, first at (4, 0) in R.
  bool matched = true;
  const std::string text = explain(half_white(5), ref, &matched);
  EXPECT_FALSE(matched);
  EXPECT_EQ(text.rfind(std::string("does not match reference ") + ref +
                           ": max error 1 at pixel (4, 0) channel R, 6 of 48 pixels (12.5%) over fail 1e-06\n", 0),
            0u)
      << text;
  EXPECT_EQ(text.find(", matches reference"), std::string::npos) << text;
  // What EXPECT_THAT prints: the expectation, then the image and what is wrong with it.
  const std::string printed = std::string(", does not match reference ") + ref + ": max error 1 at pixel (4, 0) channel R";
  EXPECT_NONFATAL_FAILURE(EXPECT_THAT(half_white(5), MatchesReference(ref)), printed);
  // Every file it names is absolute, there, and where the test's name and the reference's stem say.
  const fs::path dir = results / this_test();
  const std::vector<std::pair<std::string, fs::path>> files = {
      {"actual:", dir / "half-text.actual.png"},     {"expected:", dir / "half-text.expected.png"},
      {"diff:", dir / "half-text.diff.png"},         {"alpha:", dir / "half-text.alpha-diff.png"},
      {"triptych:", dir / "half-text.triptych.png"}};
  for (const auto& [label, path] : files) {
    EXPECT_EQ(artefact(text, label), path.string()) << label << " in\n" << text;
    EXPECT_TRUE(fs::is_regular_file(path)) << path;
  }
  EXPECT_NE(text.find(std::string("Comparing \"") + ref + "\" and \"" + (dir / "half-text.actual.png").string() + "\""),
            std::string::npos)
      << text;
  // The kept files: the actual image (column 4 opaque white), the reference's copy (transparent).
  const Image actual = splinefig::read_image((dir / "half-text.actual.png").string());
  EXPECT_EQ(actual.at(4, 2, 3), 1.0f);
  EXPECT_EQ(splinefig::read_image((dir / "half-text.expected.png").string()).at(4, 2, 3), 0.0f);
}

TEST(MatchesReference, TheAlphaDiffIsWrittenOnlyWhenAlphaDiffers) {
  const fs::path results = scratch("results-alpha");
  fs::remove_all(results);
  const Env env_results("SPLINEFIG_TEST_RESULTS", results.string());
  const std::string ref = scratch("half-alpha.png").string();
  {
    const Env update("SPLINEFIG_UPDATE_REFERENCES", "1");
    EXPECT_THAT(half_white(4), MatchesReference(ref));
  }
  const fs::path alpha_diff = results / this_test() / "half-alpha.alpha-diff.png";
  // Alpha differs in column 4 (0 against 1): the alpha diff is 1 there (scaled by 1 / max error
  // = 1) and 0 elsewhere.
  std::string text = explain(half_white(5), ref);
  ASSERT_TRUE(fs::exists(alpha_diff)) << text;
  EXPECT_EQ(artefact(text, "alpha:"), alpha_diff.string());
  const Image a = splinefig::read_image(alpha_diff.string());
  ASSERT_EQ(a.channels, 1);
  EXPECT_EQ(a.at(4, 3, 0), 1.0f);
  EXPECT_EQ(a.at(3, 3, 0), 0.0f);
  EXPECT_EQ(a.at(5, 3, 0), 0.0f);
  // The same coverage in another colour (grey 0.5 for white): no alpha diff, and the one the
  // earlier failure left is gone, so that what is there belongs to the last failure.
  text = explain(half_grey(4), ref);
  EXPECT_EQ(text.rfind(std::string("does not match reference ") + ref + ": ", 0), 0u) << text;
  EXPECT_FALSE(fs::exists(alpha_diff)) << text;
  EXPECT_EQ(text.find(".alpha-diff.png"), std::string::npos) << text;
  EXPECT_NE(text.find("  alpha:    the same in both"), std::string::npos) << text;
  EXPECT_TRUE(fs::exists(results / this_test() / "half-alpha.diff.png"));
}

TEST(MatchesReference, TheArtefactsDoNotDependOnTheWorkingDirectory) {
  const fs::path results = scratch("results-cwd");
  fs::remove_all(results);
  const Env env_results("SPLINEFIG_TEST_RESULTS", results.string());
  const fs::path base = scratch("cwd");
  fs::remove_all(base);
  fs::create_directories(base / "refs");
  fs::create_directories(base / "elsewhere" / "deeper");
  const fs::path ref = base / "refs" / "half-cwd.png";
  {
    const Env update("SPLINEFIG_UPDATE_REFERENCES", "1");
    EXPECT_THAT(half_white(4), MatchesReference(ref.string()));
  }
  // No reference root: <results>/<test>/<stem>. With SPLINEFIG_REFERENCE_ROOT: the reference's
  // path relative to it. The same from a directory holding the reference, one beside it and /,
  // with the reference given by absolute path and by a path relative to where the test runs.
  for (const bool rooted : {false, true}) {
    const Env root("SPLINEFIG_REFERENCE_ROOT", rooted ? base.string() : std::string());
    const fs::path want = rooted ? results / this_test() / "refs" / "half-cwd.actual.png"
                                 : results / this_test() / "half-cwd.actual.png";
    for (const fs::path& cwd : {base, base / "refs", base / "elsewhere" / "deeper", fs::path("/")}) {
      const InDirectory in(cwd);
      for (const fs::path& given : {ref, ref.lexically_relative(cwd)}) {
        const std::string text = explain(half_white(5), given.string());
        EXPECT_EQ(artefact(text, "actual:"), want.string()) << "from " << cwd << " as " << given << ":\n" << text;
        EXPECT_EQ(text.rfind(std::string("does not match reference ") + ref.string() + ": ", 0), 0u) << text;
      }
    }
    EXPECT_TRUE(fs::is_regular_file(want)) << want;
  }
  // Nothing was written anywhere else under the results.
  std::size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(results)) files += e.is_regular_file();
  EXPECT_EQ(files, 2u * 5u);
}
