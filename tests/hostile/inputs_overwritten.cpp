// No output replaces a file the command reads: `render -o` naming the spec's [[image]] file, an
// [[axes.image]] file, a points_file or a knots_file, by any spelling (./x, a symbolic link, a
// hard link), and `figures` writing a figure, index.json or index.html over a file one of its
// specs names, are refused with one line and exit 2 before anything is written; the input
// keeps its bytes.
#include "hostile.hpp"

using namespace splinefig::hostile;

namespace {

const std::string kCanvas = "[canvas]\nwidth = 24\nheight = 24\n";

// A small PNG made by the program itself (any image it reads will do).
void make_png(const fs::path& dir, const std::string& name) {
  write_file(dir / "maker.toml", kCanvas + "[[circle]]\ncenter = [12, 12]\nradius = 8\nfill = \"#336699\"\n");
  REQUIRE(run_in(dir, {"render", "maker.toml", "-o", name}).code == 0);
  fs::remove(dir / "maker.toml");
}

void check_refused_output(const fs::path& dir, const std::vector<std::string>& args, const fs::path& input,
                          const std::string& says) {
  const std::string before = splinefig::test::slurp(input);
  REQUIRE_FALSE(before.empty());
  const Outcome o = run_in(dir, args);
  INFO(args.back() << " (" << o.seconds << " s): " << o.err);
  CHECK_FALSE(o.killed);
  CHECK(o.code == 2);
  CHECK(splinefig::test::count_lines(o.err) == 1);
  CHECK_THAT(o.err, Catch::Contains(says) && Catch::Contains("an input"));
  CHECK(splinefig::test::slurp(input) == before);
}

}  // namespace

TEST_CASE("render -o naming the spec's image file, by any spelling, is refused and the image kept") {
  const fs::path dir = scratch();
  make_png(dir, "pic.png");
  fs::create_directories(dir / "sub");
  write_file(dir / "spec.toml", kCanvas + "[[image]]\nfile = \"pic.png\"\nat = [2, 2]\n");
  fs::create_symlink("pic.png", dir / "soft.png");
  fs::create_hard_link(dir / "pic.png", dir / "hard.png");
  for (const std::string& out : std::vector<std::string>{"pic.png", "./pic.png", "sub/../pic.png", (dir / "pic.png").string(), "soft.png", "hard.png"})
    check_refused_output(dir, {"render", "spec.toml", "-o", out}, dir / "pic.png",
                         "-o " + out + ": it is spec.toml:5: image.file = \"pic.png\", an input");
  // The same spec into another file renders.
  CHECK(run_in(dir, {"render", "spec.toml", "-o", "other.png"}).code == 0);
  fs::remove_all(dir);
}

TEST_CASE("render -o naming an [[axes.image]] file, a points_file or a knots_file is refused") {
  const fs::path dir = scratch();
  make_png(dir, "tile.png");
  write_file(dir / "pts.csv", "x,y\n0,0\n1,2\n2,1\n3,3\n");
  write_file(dir / "knots.csv", "0,0\n1,2\n2,1\n3,3\n4,0\n");
  fs::create_directories(dir / "data");
  fs::create_hard_link(dir / "pts.csv", dir / "data" / "pts.png");
  fs::create_symlink("knots.csv", dir / "knots.png");
  write_file(dir / "axes.toml", kCanvas +
                                    "[[axes]]\nx_range = [0, 4]\ny_range = [0, 4]\n"
                                    "[[axes.image]]\nfile = \"tile.png\"\nextent = [0, 1, 0, 1]\n"
                                    "[[axes.series]]\npoints_file = \"data/../pts.csv\"\n"
                                    "[[axes.curve]]\nbasis = \"catmull-rom\"\nknots_file = \"knots.csv\"\n");
  check_refused_output(dir, {"render", "axes.toml", "-o", "tile.png"}, dir / "tile.png", "axes.image.file = \"tile.png\"");
  check_refused_output(dir, {"render", "axes.toml", "-o", "data/pts.png"}, dir / "pts.csv",
                       "axes.series.points_file = \"data/../pts.csv\"");
  check_refused_output(dir, {"render", "axes.toml", "-o", "knots.png"}, dir / "knots.csv",
                       "axes.curve.knots_file = \"knots.csv\"");
  CHECK(fs::is_symlink(dir / "knots.png"));
  // A top-level points_file as well, and an output in another directory than the spec.
  fs::create_directories(dir / "spec");
  write_file(dir / "spec" / "line.toml", kCanvas + "[[polyline]]\npoints_file = \"../pts.csv\"\n");
  check_refused_output(dir, {"render", "spec/line.toml", "-o", "data/pts.png"}, dir / "pts.csv",
                       "polyline.points_file = \"../pts.csv\"");
  fs::remove_all(dir);
}

TEST_CASE("figures writing over an image one of its specs reads is refused before anything is written") {
  const fs::path dir = scratch();
  fs::create_directories(dir / "specs");
  fs::create_directories(dir / "out");
  make_png(dir, "out/fig.png");
  make_png(dir, "out/other.png");
  // fig.toml reads its own output; then a spec reading another figure's output.
  write_file(dir / "specs" / "fig.toml", kCanvas + "[[image]]\nfile = \"../out/fig.png\"\n");
  check_refused_output(dir, {"figures", "--specs", "specs", "--out", "out"}, dir / "out" / "fig.png",
                       "out/fig.png: it is specs/fig.toml:5: image.file = \"../out/fig.png\", an input");
  write_file(dir / "specs" / "fig.toml", kCanvas + "[[image]]\nfile = \"../out/other.png\"\n");
  write_file(dir / "specs" / "other.toml", kCanvas);
  check_refused_output(dir, {"figures", "--specs", "specs", "--out", "out", "--format", "svg,png"},
                       dir / "out" / "other.png", "out/other.png: it is specs/fig.toml:5");
  CHECK_FALSE(fs::exists(dir / "out" / "fig.svg"));
  CHECK_FALSE(fs::exists(dir / "out" / "other.svg"));
  CHECK_FALSE(fs::exists(dir / "out" / "index.json"));
  // A data file named index.json in the output directory is an input as well.
  write_file(dir / "specs" / "fig.toml", kCanvas + "[[polyline]]\npoints_file = \"../out/index.json\"\n");
  write_file(dir / "out" / "index.json", "0,0\n1,1\n");
  check_refused_output(dir, {"figures", "--specs", "specs", "--out", "out"}, dir / "out" / "index.json",
                       "out/index.json: it is specs/fig.toml:5");
  // Without the reading spec the run renders.
  fs::remove(dir / "specs" / "fig.toml");
  CHECK(run_in(dir, {"figures", "--specs", "specs", "--out", "out"}).code == 0);
  fs::remove_all(dir);
}
