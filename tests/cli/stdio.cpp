// `-` for standard input and output: render, resample and diff read and write through stdin and
// stdout the very bytes they read and write as files (compared byte for byte with the file
// runs), a failure leaves stdout empty, and what makes no sense (diff - -) is refused.
#include "cli/run.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using splinefig::test::count_lines;
using splinefig::test::run;
using splinefig::test::slurp;

namespace {

const std::string kBias = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/bias.toml";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("splinefig-stdio-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// The current directory set to `dir` while it lives (run() starts the command there).
struct InDirectory {
  fs::path old = fs::current_path();
  explicit InDirectory(const fs::path& dir) { fs::current_path(dir); }
  ~InDirectory() { fs::current_path(old); }
};

void check_one_line_failure(const splinefig::test::Run& r, int code, const std::string& says) {
  INFO("stderr: " << r.err);
  CHECK(r.code == code);
  CHECK(r.out.empty());
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains(says));
}

}  // namespace

TEST_CASE("stdio: render -o - writes the PNG that -o FILE.png writes, and --format picks another") {
  const fs::path dir = scratch("render-out");
  const std::string file = (dir / "bias.png").string();
  REQUIRE(run({"render", kBias, "-o", file}).code == 0);
  const std::string png = slurp(file);
  REQUIRE(png.size() > 1000);
  const auto r = run({"render", kBias, "-o", "-"});
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  CHECK(r.out == png);

  REQUIRE(run({"render", kBias, "-o", (dir / "bias.svg").string()}).code == 0);
  const auto svg = run({"render", kBias, "-o", "-", "--format", "svg"});
  CHECK(svg.code == 0);
  CHECK(svg.out == slurp(dir / "bias.svg"));
  CHECK(svg.out.starts_with("<?xml"));

  // An output name without a known extension takes --format too.
  REQUIRE(run({"render", kBias, "-o", (dir / "plot").string(), "--format", "png"}).code == 0);
  CHECK(slurp(dir / "plot") == png);
  fs::remove_all(dir);
}

TEST_CASE("stdio: render - reads the spec from stdin, its relative files from the current directory") {
  const fs::path dir = scratch("render-in");
  // The spec is named "stdin" in what it writes (the PNG's description), so a file of that name
  // gives the same bytes.
  fs::copy_file(kBias, dir / "stdin.toml");
  REQUIRE(run({"render", (dir / "stdin.toml").string(), "-o", (dir / "file.png").string()}).code == 0);
  const auto r = run({"render", "-", "-o", (dir / "piped.png").string()}, slurp(kBias));
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  CHECK(slurp(dir / "piped.png") == slurp(dir / "file.png"));

  // An [[image]] named relatively: found in the current directory, and the output the same as
  // the spec file's in that directory.
  const std::string spec =
      "[canvas]\nwidth = 8\nheight = 8\n[[image]]\nfile = \"pic.png\"\nat = [2, 2]\n";
  {
    std::ofstream(dir / "stdin.toml") << spec;
  }
  REQUIRE(run({"resample", (dir / "file.png").string(), "-o", (dir / "pic.png").string(), "--size", "4x4",
               "--filter", "box"}).code == 0);
  REQUIRE(run({"render", (dir / "stdin.toml").string(), "-o", (dir / "with-image.png").string()}).code == 0);
  {
    const InDirectory here(dir);
    const auto p = run({"render", "-", "-o", "-"}, spec);
    CHECK(p.code == 0);
    CHECK(p.err.empty());
    CHECK(p.out == slurp(dir / "with-image.png"));
  }
  // Elsewhere the file is missing, and the error says where it was looked for.
  const auto missing = run({"render", "-", "-o", (dir / "x.png").string()}, spec);
  CHECK(missing.code != 0);
  CHECK_THAT(missing.err, Catch::Contains("stdin"));
  CHECK_THAT(missing.err, Catch::Contains("pic.png"));
  CHECK(!fs::exists(dir / "x.png"));
  fs::remove_all(dir);
}

TEST_CASE("stdio: render - -o FILE refuses a FILE the spec on stdin reads, as for a spec file") {
  const fs::path dir = scratch("render-over-input");
  REQUIRE(run({"render", kBias, "-o", (dir / "big.png").string()}).code == 0);
  REQUIRE(run({"resample", (dir / "big.png").string(), "-o", (dir / "pic.png").string(), "--size", "4x4", "--filter",
               "box"}).code == 0);
  { std::ofstream(dir / "knots.csv") << "x,y\n0,0\n1,2\n3,1\n4,3\n"; }
  const std::string spec =
      "[canvas]\nwidth = 200\nheight = 150\n[[image]]\nfile = \"pic.png\"\nat = [2, 2]\n"
      "[axes]\n[[axes.markers]]\npoints_file = \"knots.csv\"\n";
  const std::string pic = slurp(dir / "pic.png"), csv = slurp(dir / "knots.csv");
  const InDirectory here(dir);
  // Each input, by the name the spec gives, by another spelling and by a hard link: refused
  // before anything is written, the input as it was.
  fs::create_directories(dir / "sub");
  fs::create_hard_link(dir / "pic.png", dir / "link.png");
  for (const std::vector<std::string>& out :
       {std::vector<std::string>{"-o", "pic.png"}, {"-o", "sub/../pic.png"}, {"-o", (dir / "link.png").string()},
        {"-o", "knots.csv", "--format", "png"}}) {
    std::vector<std::string> args{"render", "-"};
    args.insert(args.end(), out.begin(), out.end());
    const auto r = run(args, spec);
    INFO(out[1]);
    check_one_line_failure(r, 2, "-o " + out[1] + ": it is stdin:");
    CHECK_THAT(r.err, Catch::Contains(", an input (write to another file)"));
    CHECK_THAT(r.err, Catch::Contains(out[1] == "knots.csv" ? "points_file = \"knots.csv\"" : "file = \"pic.png\""));
    CHECK_THAT(r.err, !Catch::Contains("stdin.toml"));  // said as stdin, not as a scratch copy
  }
  CHECK(slurp(dir / "pic.png") == pic);
  CHECK(slurp(dir / "knots.csv") == csv);
  // Another name is written as before.
  CHECK(run({"render", "-", "-o", "out.png"}, spec).code == 0);
  CHECK(slurp(dir / "out.png").starts_with("\x89PNG"));
  fs::current_path(here.old);
  fs::remove_all(dir);
}

TEST_CASE("stdio: resample - -o - gives the bytes of the file run, in the format --format names") {
  const fs::path dir = scratch("resample");
  const std::string src = (dir / "bias.png").string();
  REQUIRE(run({"render", kBias, "-o", src}).code == 0);
  const std::string png = slurp(src);
  for (const std::string fmt : {"png", "tif", "exr"}) {
    const std::string file = (dir / ("half." + fmt)).string();
    REQUIRE(run({"resample", src, "-o", file, "--scale", "0.5", "--filter", "catmull-rom"}).code == 0);
    std::vector<std::string> args{"resample", "-", "-o", "-", "--scale", "0.5", "--filter", "catmull-rom"};
    if (fmt != "png") args.insert(args.end(), {"--format", fmt});
    const auto r = run(args, png);
    INFO(fmt << ": " << r.err);
    CHECK(r.code == 0);
    CHECK(r.out == slurp(file));
  }
  // Not an image on stdin, or an empty stdin: one line, nothing on stdout, exit 2 as for any
  // input resample cannot read (4 is diff's code only).
  check_one_line_failure(run({"resample", "-", "-o", "-", "--scale", "0.5", "--filter", "box"}, "0,0\n1,1\n"), 2,
                         "stdin is not a PNG, EXR, JPEG or TIFF image");
  check_one_line_failure(run({"resample", "-", "-o", "-", "--scale", "0.5", "--filter", "box"}, ""), 2,
                         "stdin is empty");
  // A PNG cut short on stdin is said as stdin, not as a scratch file.
  const auto cut = run({"resample", "-", "-o", "-", "--scale", "0.5", "--filter", "box"}, png.substr(0, png.size() / 2));
  check_one_line_failure(cut, 2, "stdin");
  CHECK_THAT(cut.err, !Catch::Contains("/tmp"));
  fs::remove_all(dir);
}

TEST_CASE("stdio: diff - B compares stdin with B, and - for both is refused") {
  const fs::path dir = scratch("diff");
  const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string();
  REQUIRE(run({"render", kBias, "-o", a}).code == 0);
  REQUIRE(run({"render", kBias, "-o", b, "--scale", "0.5"}).code == 0);
  CHECK(run({"diff", "-", a}, slurp(a)).code == 0);
  const auto file = run({"diff", b, a});
  const auto piped = run({"diff", "-", a}, slurp(b));
  CHECK(file.code == 2);
  CHECK(piped.code == 2);
  // The same report, but for the name of the first image.
  CHECK(piped.out.substr(piped.out.find('\n')) == file.out.substr(file.out.find('\n')));
  CHECK(run({"diff", a, "-"}, slurp(a)).code == 0);
  check_one_line_failure(run({"diff", "-", "-"}, slurp(a)), 2, "A and B are both -");
  check_one_line_failure(run({"diff", "-", a, "--diff-image", "-"}, slurp(a)), 2, "--diff-image -: stdout holds the report");
  // What cannot be read as an image on stdin is idiff's exit 4 for diff.
  check_one_line_failure(run({"diff", "-", a}, ""), 4, "stdin is empty");
  check_one_line_failure(run({"diff", a, "-"}, "0,0\n"), 4, "stdin is not a PNG, EXR, JPEG or TIFF image");
  fs::remove_all(dir);
}

TEST_CASE("stdio: a failed write to stdout is the one-line error, and a failed render writes nothing") {
  const auto full = run({"render", kBias, "-o", "-"}, "", "/dev/full");
  INFO(full.err);
  CHECK(full.code == 2);
  CHECK(count_lines(full.err) == 1);
  CHECK_THAT(full.err, Catch::Contains("cannot write to standard output (No space left on device)"));
  check_one_line_failure(run({"render", "-", "-o", "-"}, "[canvas]\nwidth = -3\nheight = 5\n"), 2, "stdin");
  check_one_line_failure(run({"render", kBias, "-o", "-", "--format", "gif"}), 2, "--format gif: not one of png, exr, svg, pdf");
  check_one_line_failure(run({"render", kBias, "-o", "x.png", "--format", "svg"}), 2, "names another format (.png)");
}
