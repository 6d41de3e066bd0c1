// Command-line mistakes as people make them get one line in splinefig's words, read here
// letter for letter: "splinefig COMMAND: ...", the near miss of a flag, command or filter name
// suggested, a missing argument named; the alias mitchell and exact rationals in parameters.
#include "cli/run.hpp"

#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/near_miss.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

namespace fs = std::filesystem;
using splinefig::test::run;

namespace {

const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/bias.toml";
const std::string commands = "diff, eval, figures, interp, kernel, render, resample or version";

fs::path scratch() {
  const fs::path dir = fs::temp_directory_path() / ("splinefig-parse-errors-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Exit 2, nothing on stdout, exactly `line` (and its newline) on stderr.
void check_says(const std::vector<std::string>& args, const std::string& line) {
  const auto r = run(args);
  std::string cmd = "splinefig";
  for (const auto& a : args) cmd += " " + a;
  INFO(cmd << "\nstderr: " << r.err);
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK(r.err == line + "\n");
}

}  // namespace

TEST_CASE("parse errors: a near miss of a flag is named with the flag meant") {
  const std::string out = (scratch() / "x.png").string();
  check_says({"render", spec, "-o", out, "--scal", "2"}, "splinefig render: unknown option --scal (did you mean --scale?)");
  // The typo first: its value then fills the spec's place, and the typo is still what is reported.
  check_says({"render", "--scal", "2", spec, "-o", out}, "splinefig render: unknown option --scal (did you mean --scale?)");
  check_says({"render", spec, "-o", out, "--sacle=2"}, "splinefig render: unknown option --sacle (did you mean --scale?)");
  check_says({"render", spec, "-O", out}, "splinefig render: unknown option -O (did you mean -o?)");
  check_says({"resample", "in.png", "-o", out, "--filtr", "bspline"},
             "splinefig resample: unknown option --filtr (did you mean --filter?)");
  check_says({"diff", "a.png", "b.png", "--fail-percent", "1"},
             "splinefig diff: unknown option --fail-percent (did you mean --failpercent?)");
  // No near miss: the command that has the flag, or its help.
  check_says({"render", spec, "-o", out, "--filter", "mitchell"},
             "splinefig render: unknown option --filter (--filter is an option of resample, not of render)");
  check_says({"kernel", "catmull-rom", "-v"},
             "splinefig kernel: unknown option -v (-v is an option of diff, figures, render or resample, not of kernel)");
  check_says({"render", spec, "-o", out, "--version"},
             "splinefig render: unknown option --version (--version is an option of splinefig itself: splinefig --version)");
  check_says({"render", spec, "-o", out, "--frobnicate"}, "splinefig render: unknown option --frobnicate (see splinefig render --help)");
  // The unknown flag comes before a missing argument, which it may well have been meant as.
  check_says({"render", spec, "--outptu", out}, "splinefig render: unknown option --outptu (did you mean --output?)");
}

TEST_CASE("parse errors: before the command, splinefig's own flags and the command names") {
  check_says({"--Version"}, "splinefig: unknown option --Version (did you mean --version?)");
  check_says({"-v"}, "splinefig: unknown option -v (did you mean --version?)");
  check_says({"-V"}, "splinefig: unknown option -V (did you mean --version?)");
  check_says({"--render"}, "splinefig: unknown option --render (did you mean render?)");
  check_says({"--frobnicate"},
             "splinefig: unknown option --frobnicate (splinefig takes a command first: " + commands + "; see splinefig --help)");
  check_says({}, "splinefig: a command is required: " + commands + " (see splinefig --help)");
  check_says({"rendr", spec}, "splinefig: unknown command 'rendr' (did you mean render? commands: " + commands +
                                  "; see splinefig --help)");
  for (const char* dashes : {"-", "--", "---"})
    check_says({dashes}, std::string("splinefig: unknown option ") + dashes + " (splinefig takes a command first: " + commands +
                             "; see splinefig --help)");
  check_says({"frobnicate"}, "splinefig: unknown command 'frobnicate' (commands: " + commands + "; see splinefig --help)");
  const auto r = run({"--version"});
  CHECK(r.code == 0);
  CHECK(r.out.rfind("splinefig ", 0) == 0);
}

TEST_CASE("parse errors: a missing argument is named in words, with the command's usage") {
  check_says({"diff", "a.png"}, "splinefig diff: missing B, the second (actual) image; usage: splinefig diff A B [options]");
  check_says({"diff"}, "splinefig diff: missing A, the first (expected) image and B, the second (actual) image; "
                       "usage: splinefig diff A B [options]");
  check_says({"render", spec}, "splinefig render: missing -o/--output PATH; usage: splinefig render SPEC -o PATH [options]");
  // A positional is named by the first clause of its description, the rest being for --help.
  check_says({"render"}, "splinefig render: missing SPEC, the figure spec (TOML, see docs/spec.md) and -o/--output PATH; "
                         "usage: splinefig render SPEC -o PATH [options]");
  check_says({"resample"}, "splinefig resample: missing IN, the input image (PNG, EXR, TIFF or JPEG), -o/--output PATH, "
                           "and --filter SPEC; usage: splinefig resample IN -o PATH --filter SPEC [options]");
  check_says({"diff", "a.png", "b.png", "c.png"},
             "splinefig diff: unexpected argument 'c.png' (usage: splinefig diff A B [options]; see splinefig diff --help)");
  check_says({"render", spec, "-o", "x.png", "--", "c.png"},
             "splinefig render: unexpected argument 'c.png' (usage: splinefig render SPEC -o PATH [options]; see splinefig render --help)");
  check_says({"diff", "a.png", "--", "b.png", "c.png"},
             "splinefig diff: unexpected argument 'c.png' (usage: splinefig diff A B [options]; see splinefig diff --help)");
  check_says({"version", "x"}, "splinefig version: unexpected argument 'x' (usage: splinefig version [options]; see splinefig version --help)");
}

TEST_CASE("parse errors: a flag's value that is missing or of the wrong kind") {
  const std::string out = (scratch() / "x.png").string();
  check_says({"render", spec, "-o"}, "splinefig render: -o/--output needs a value (PATH)");
  check_says({"kernel", "--basis", "bspline", "--from"}, "splinefig kernel: --from needs a value (a number)");
  check_says({"render", spec, "-o", out, "--scale", "abc"}, "splinefig render: --scale abc: not a number");
  check_says({"render", spec, "-o", out, "--threads", "1.5"}, "splinefig render: --threads 1.5: not an integer");
  check_says({"render", spec, "-o", out, "-o", out}, "splinefig render: -o/--output is given more than once");
}

TEST_CASE("parse errors: a near miss of a filter or basis name is named with the name meant") {
  const std::string known_bases = "catmull-rom, cardinal, bspline, tensioned-bspline, beta, uniform-bspline, mitchell-netravali";
  check_says({"resample", "in.png", "-o", "out.png", "--scale", "2", "--filter", "mitchel"},
             "splinefig resample: --filter: unknown filter 'mitchel' (did you mean mitchell-netravali? known: box, tent, "
             "lanczos3 and the bases " + known_bases + ")");
  check_says({"resample", "in.png", "-o", "out.png", "--scale", "2", "--filter", "lanczos"},
             "splinefig resample: --filter: unknown filter 'lanczos' (did you mean lanczos3? known: box, tent, lanczos3 and "
             "the bases " + known_bases + ")");
  check_says({"eval", "--basis", "catmul-rom"},
             "splinefig eval: --basis: unknown basis 'catmul-rom' (did you mean catmull-rom? known: " + known_bases + ")");
  check_says({"eval", "--basis", "gauss"}, "splinefig eval: --basis: unknown basis 'gauss' (known: " + known_bases + ")");
}

TEST_CASE("parse errors: near misses are the nearest names within a few edits or begun by the word") {
  using splinefig::near_misses;
  const std::vector<std::string> known{"scale", "scales", "threads", "dpi", "output"};
  CHECK(near_misses("scal", known) == std::vector<std::string>{"scale"});
  CHECK(near_misses("SCALE", known) == std::vector<std::string>{"scale"});
  CHECK(near_misses("tehrads", known) == std::vector<std::string>{"threads"});  // one swap
  CHECK(near_misses("out", known) == std::vector<std::string>{"output"});        // begun by the word
  CHECK(near_misses("dp", known).empty());                                         // 2 letters: exact (case aside) only
  CHECK(near_misses("xyz", known).empty());
  CHECK(near_misses("scalee", known) == std::vector<std::string>{"scale", "scales"});
  CHECK(splinefig::edit_distance("kitten", "sitting") == 3);
  CHECK(splinefig::edit_distance("ab", "ba") == 1);
}

TEST_CASE("filters: mitchell is mitchell-netravali, as OpenImageIO and libvips name it") {
  const fs::path dir = scratch();
  const std::string in = (dir / "in.png").string();
  REQUIRE(run({"render", spec, "-o", in, "--scale", "0.25"}).code == 0);
  std::vector<std::string> outs;
  for (const char* f : {"mitchell", "mitchell-netravali", "mitchell:b=1/3,c=1/3", "catmull-rom"}) {
    const std::string out = (dir / (std::string("out-") + std::to_string(outs.size()) + ".png")).string();
    const auto r = run({"resample", in, "-o", out, "--scale", "1.5", "--filter", f});
    INFO(f << ": " << r.err);
    REQUIRE(r.code == 0);
    outs.push_back(splinefig::test::slurp(out));
  }
  CHECK(outs[0] == outs[1]);
  CHECK(outs[2] == outs[1]);
  CHECK(outs[3] != outs[1]);  // the comparison can tell filters apart
  CHECK(splinefig::parse_basis("mitchell").spec == splinefig::parse_basis("mitchell-netravali").spec);
}

TEST_CASE("parameters: exact rationals P/Q, as the docs write them") {
  // k(s) of M(1/3, 1/3) on [0, 1) is (7s^3 - 12s^2 + 16/3) / 6: k(0) = 8/9, k(1/2) = 77/144, k(1/4) = 901/1152.
  const auto r = run({"kernel", "--basis", "mitchell-netravali:b=1/3,c=1/3", "--from", "0", "--to", "0.5", "--step", "0.25"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  std::istringstream lines(r.out);
  std::vector<double> k;
  for (std::string line; std::getline(lines, line);) k.push_back(std::stod(line.substr(line.find(',') + 1)));
  REQUIRE(k.size() == 3);
  CHECK(k[0] == Approx(8.0 / 9).epsilon(1e-15));
  CHECK(k[1] == Approx(901.0 / 1152).epsilon(1e-15));
  CHECK(k[2] == Approx(77.0 / 144).epsilon(1e-15));
  // P/Q is the double nearest the rational: 2/6 is 1/3, bit for bit; a decimal 0.3333 is not.
  using splinefig::parse_basis;
  CHECK(parse_basis("mitchell-netravali:b=2/6,c=-3/9").m == parse_basis("mitchell-netravali:b=1/3,c=-1/3").m);
  CHECK(parse_basis("mitchell-netravali:b=1/3,c=1/3").m == splinefig::mitchell_netravali_basis(1.0 / 3, 1.0 / 3).m);
  CHECK(parse_basis("mitchell-netravali:b=0.3333,c=1/3").m != parse_basis("mitchell-netravali:b=1/3,c=1/3").m);
  CHECK(parse_basis("cardinal:a=+1/2").m == parse_basis("cardinal:a=0.5").m);
  check_says({"kernel", "--basis", "mitchell:b=1/0"}, "splinefig kernel: --basis: mitchell-netravali: value of 'b' divides by zero: '1/0'");
  check_says({"kernel", "--basis", "cardinal:a=1/3.0"},
             "splinefig kernel: --basis: cardinal: value of 'a' is not a number or a fraction P/Q of integers: '1/3.0'");
  check_says({"kernel", "--basis", "cardinal:a=1/-3"},
             "splinefig kernel: --basis: cardinal: value of 'a' is not a number or a fraction P/Q of integers: '1/-3'");
  check_says({"kernel", "--basis", "cardinal:a=/3"},
             "splinefig kernel: --basis: cardinal: value of 'a' is not a number or a fraction P/Q of integers: '/3'");
}
