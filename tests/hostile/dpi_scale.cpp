// The resolution a file records is --dpi times --scale (the figure keeps its printed size), and
// that is what the dpi limit bounds, for PNG, SVG and PDF alike, before anything is written.
#include "hostile.hpp"

using namespace splinefig::hostile;

namespace {
const std::string kSpec = "[canvas]\nwidth = 40\nheight = 30\n[[circle]]\ncenter = [20, 15]\nradius = 9\n";
}

TEST_CASE("a file of 20000 dpi (--dpi 5000 at --scale 4) is refused for rasters and vectors") {
  for (const char* ext : {"png", "svg", "pdf"}) {
    const fs::path dir = scratch();
    write_file(dir / "s.toml", kSpec);
    const std::string out = std::string("s.") + ext;
    const Outcome o = run_in(dir, {"render", "s.toml", "-o", out, "--dpi", "5000", "--scale", "4"});
    INFO(ext << ": " << o.err);
    CHECK(o.code == 2);
    CHECK(splinefig::test::count_lines(o.err) == 1);
    CHECK_THAT(o.err, Catch::Contains("dpi 5000 at scale 4 is 20000 dots per inch in the file, outside [1, 10000]"));
    CHECK_FALSE(fs::exists(dir / out));
    // Within the limit at that scale, the same request is written.
    const Outcome ok = run_in(dir, {"render", "s.toml", "-o", out, "--dpi", "2500", "--scale", "4"});
    CHECK(ok.code == 0);
    CHECK(fs::exists(dir / out));
    fs::remove_all(dir);
  }
}
