// A points_file that is not CSV (a password file, a binary, /proc/self/mem) is refused without
// quoting any of it: "not a CSV file" when its first data line does not parse, a located read
// error when it cannot be read. A value that is quoted (a bad field after good points) is at
// most 24 bytes, escaped.
#include "hostile.hpp"

using namespace splinefig::hostile;

namespace {

const std::string kCanvas = "[canvas]\nwidth = 24\nheight = 24\n";

Outcome render_points(const fs::path& dir, const std::string& file) {
  return render_spec(dir, "data", kCanvas + "[[axes]]\n[[axes.series]]\npoints_file = \"" + file + "\"\n");
}

}  // namespace

TEST_CASE("a points_file that is not CSV is 'not a CSV file', and no line of it is echoed") {
  const fs::path dir = scratch();
  // /etc/shadow's form (that file is readable by root only).
  write_file(dir / "shadow", "root:$y$j9T$Vb9secret0:20228:0:99999:7:::\ndaemon:*:20228:0:99999:7:::\nbin:*:20228:0:99999:7:::\n");
  write_file(dir / "config.ini", "[section]\ntoken = hunter2,opensesame\n");
  for (const std::string file : {"shadow", "config.ini", "/etc/passwd"}) {
    const Outcome o = render_points(dir, file);
    INFO(file << ": " << o.err);
    CHECK(o.code == 2);
    CHECK(splinefig::test::count_lines(o.err) == 1);
    CHECK_THAT(o.err, Catch::StartsWith("splinefig render: data.toml:6: axes[0].series[0].points_file: " + file + " line 2: ") &&
                          Catch::Contains("not a CSV file (field 1 of its first data line is not a number)"));
    for (const std::string secret : {"daemon", "secret", "20228", "hunter2", "token", "root", "x:"})
      CHECK(o.err.find(secret) == std::string::npos);
    CHECK_FALSE(fs::exists(dir / "data.png"));
  }
  fs::remove_all(dir);
}

TEST_CASE("a points_file that cannot be read is a located read error") {
  const fs::path dir = scratch();
  const Outcome o = render_points(dir, "/proc/self/mem");
  INFO(o.err);
  CHECK(o.code == 2);
  CHECK(o.err == "splinefig render: data.toml:6: axes[0].series[0].points_file: /proc/self/mem line 1: a read error: the input is not a "
                 "readable file\n");
  fs::remove_all(dir);
}

TEST_CASE("a bad field after good points is quoted, at most 24 bytes and escaped") {
  const fs::path dir = scratch();
  write_file(dir / "pts.csv", "0,0\n1,1\n2," + std::string(100, 'A') + "\x1b\n");
  Outcome o = render_points(dir, "pts.csv");
  CHECK(o.code == 2);
  CHECK(o.err == "splinefig render: data.toml:6: axes[0].series[0].points_file: pts.csv line 3, field 2: '" +
                     std::string(24, 'A') + "...' is not a number\n");
  write_file(dir / "pts.csv", "0,0\n1,\x1b[2J\n");
  o = render_points(dir, "pts.csv");
  CHECK(o.err == "splinefig render: data.toml:6: axes[0].series[0].points_file: pts.csv line 2, field 2: '\\x1b[2J' is not a number\n");
  fs::remove_all(dir);
}

// docs/spec.md: a spec may name a file outside its own directory, by an absolute path or
// through "..", as any program's input may; only what it may learn or make splinefig do is
// bounded.
TEST_CASE("a spec reads data files outside its directory, by an absolute path or through ..") {
  const std::string kPlot = "[canvas]\nwidth = 320\nheight = 240\n";
  const fs::path dir = scratch();
  fs::create_directories(dir / "specs");
  write_file(dir / "points.csv", "0,0\n1,1\n2,0\n");
  // From the parent directory: ".." is taken from the spec's directory, not the working one.
  write_file(dir / "specs" / "up.toml", kPlot + "[[axes]]\n[[axes.series]]\npoints_file = \"../points.csv\"\n");
  write_file(dir / "specs" / "absolute.toml",
             kPlot + "[[axes]]\n[[axes.series]]\npoints_file = \"" + (dir / "points.csv").string() + "\"\n");
  for (const std::string name : {"up", "absolute"}) {
    const Outcome o = run_in(dir, {"render", "specs/" + name + ".toml", "-o", name + ".png"});
    INFO(name << ": " << o.err);
    CHECK(o.code == 0);
    CHECK(o.err.empty());
    CHECK(fs::exists(dir / (name + ".png")));
  }
  fs::remove_all(dir);
}
