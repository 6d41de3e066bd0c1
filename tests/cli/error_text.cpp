// What error lines show of the user's input: a UTF-8 byte order mark before CSV data is
// skipped (a spec's is skipped by the TOML reader), control characters and bytes >= 0x80
// echoed from the input are written as \xNN, and an image library's error text stays on the
// one line of the message.
#include "cli/run.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <unistd.h>

namespace fs = std::filesystem;
using splinefig::test::count_lines;
using splinefig::test::run;
using splinefig::test::slurp;

namespace {

const std::string bom = "\xef\xbb\xbf";
const std::string knots = "0,0\n1,2\n3,3\n4,1\n6,0\n";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("splinefig-errtext-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// One line, every byte printable ASCII but the final newline.
void check_clean_line(const std::string& err) {
  INFO("stderr: " << err);
  CHECK(count_lines(err) == 1);
  REQUIRE_FALSE(err.empty());
  CHECK(err.back() == '\n');
  bool clean = true;
  for (std::size_t i = 0; i + 1 < err.size(); ++i) {
    const auto c = static_cast<unsigned char>(err[i]);
    clean = clean && c >= 0x20 && c < 0x7f;
  }
  CHECK(clean);
}

}  // namespace

TEST_CASE("eval and interp skip a byte order mark before the first line of CSV") {
  const auto plain = run({"eval", "--basis", "bspline"}, knots);
  REQUIRE(plain.code == 0);
  const auto marked = run({"eval", "--basis", "bspline"}, bom + knots);
  INFO(marked.err);
  CHECK(marked.code == 0);
  CHECK(marked.out == plain.out);
  const auto iplain = run({"interp", "--output", "bspline"}, knots);
  const auto imarked = run({"interp", "--output", "bspline"}, bom + knots);
  CHECK(imarked.code == 0);
  CHECK(imarked.out == iplain.out);
  // Only at the very start: elsewhere it is a bad field, named.
  const auto inner = run({"eval", "--basis", "bspline"}, "0,0\n" + bom + "1,2\n3,3\n4,1\n");
  CHECK(inner.code == 2);
  CHECK_THAT(inner.err, Catch::Contains("stdin line 2, field 1: '\\xef\\xbb\\xbf1' is not a number"));
  check_clean_line(inner.err);
}

TEST_CASE("error lines show raw bytes and control characters of the input escaped, as xNN") {
  auto r = run({"eval", "--basis", "bspline"}, "0,0\n1,\xff\x01\x1b[31m\n");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("stdin line 2, field 2: '\\xff\\x01\\x1b[31m' is not a number"));
  check_clean_line(r.err);
  r = run({"eval", "--basis", "cardinal:a=\xff\x1b"}, knots);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("'\\xff\\x1b'"));
  check_clean_line(r.err);
  r = run({"ev\xe9l"});
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("unknown command 'ev\\xe9l'"));
  check_clean_line(r.err);
  r = run({"eval", "--basis", "bspline", "--grain", "1\n2"}, knots);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("'1\\x0a2'"));
  check_clean_line(r.err);

  // A spec's key echoed in its error, by render and by figures.
  const fs::path dir = scratch("spec");
  fs::create_directories(dir / "specs");
  std::ofstream(dir / "specs" / "key.toml") << "[canvas]\nwidth = 64\nheight = 48\n\"k\xc3\xa9y\" = 1\n";
  r = run({"render", (dir / "specs" / "key.toml").string(), "-o", (dir / "k.png").string()});
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("key.toml:4: canvas.k\\xc3\\xa9y: unknown key"));
  check_clean_line(r.err);
  r = run({"figures", "--specs", (dir / "specs").string(), "--out", (dir / "out").string()});
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("key.toml:4: canvas.k\\xc3\\xa9y: unknown key"));
  CHECK(r.err.find("\xc3") == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("a spec with a byte order mark renders as without it") {
  const fs::path dir = scratch("bom-spec");
  const std::string spec = "title = \"x\"\n[canvas]\nwidth = 64\nheight = 48\n[[polyline]]\npoints = [[4, 4], [60, 44]]\n";
  // The same file name in two directories: the name goes into the PNG's description.
  fs::create_directories(dir / "plain");
  fs::create_directories(dir / "bom");
  std::ofstream(dir / "plain" / "fig.toml") << spec;
  std::ofstream(dir / "bom" / "fig.toml") << bom << spec;
  REQUIRE(run({"render", (dir / "plain" / "fig.toml").string(), "-o", (dir / "plain.png").string()}).code == 0);
  const auto r = run({"render", (dir / "bom" / "fig.toml").string(), "-o", (dir / "bom.png").string()});
  CHECK(r.code == 0);
  CHECK((slurp(dir / "bom.png") == slurp(dir / "plain.png")));
  fs::remove_all(dir);
}

TEST_CASE("image files cut short: the image library's error is one line") {
  const fs::path dir = scratch("images");
  const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/bbasis.toml";
  for (const char* ext : {"png", "exr"}) {
    const fs::path full = dir / (std::string("full.") + ext), cut = dir / (std::string("cut.") + ext);
    REQUIRE(run({"render", spec, "-o", full.string(), "--scale", "0.25"}).code == 0);
    const std::string bytes = slurp(full);
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    auto r = run({"diff", full.string(), cut.string()});
    CHECK(r.code == 4);
    check_clean_line(r.err);
    r = run({"resample", cut.string(), "-o", (dir / "o.png").string(), "--filter", "bspline", "--scale", "0.5"});
    CHECK(r.code == 2);
    check_clean_line(r.err);
    CHECK_FALSE(fs::exists(dir / "o.png"));
  }
  fs::remove_all(dir);
}
