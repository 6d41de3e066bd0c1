// A stroke whose outline would need gigabytes (hairpin turns with round joins, each join's arc
// flattened within 1e-4 px) is refused from an estimate made before the outline is built,
// naming the spec, the item and the limit; a smaller one of the same kind draws.
#include "hostile.hpp"

#include <cstdio>

using namespace splinefig::hostile;

namespace {

// n points alternating between x = 0 and x = 400, y rising by one a point, as a points_file.
std::string hairpin_csv(int n) {
  std::string csv;
  csv.reserve(static_cast<std::size_t>(n) * 12);
  char buf[32];
  for (int i = 0; i < n; ++i) {
    std::snprintf(buf, sizeof buf, "%d,%d\n", i % 2 ? 400 : 0, i);
    csv += buf;
  }
  return csv;
}

std::string hairpin_spec(int n, double width) {
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "[axes]\nx_range = [0, 400]\ny_range = [0, %d]\n[[axes.series]]\npoints_file = \"hair.csv\"\nwidth = %g\n",
                n, width);
  return buf;
}

}  // namespace

TEST_CASE("a series of 8e4 hairpin turns with round joins (2 GB of outline) is refused before it is built") {
  // Each turn of a pen 200 px wide is an arc of about 1100 vertices: 9e7 in all (1.2e8, 3.9 GB and
  // two minutes before the sweep's limit stopped it, for the 10^6-point version of width 2).
  const fs::path dir = scratch();
  write_file(dir / "hair.csv", hairpin_csv(80000));
  const Outcome o = render_spec(dir, "hair", hairpin_spec(80000, 200));
  INFO(o.seconds << " s: " << o.err);
  CHECK_FALSE(o.killed);
  CHECK(o.code == 2);
  CHECK(splinefig::test::count_lines(o.err) == 1);
  CHECK_THAT(o.err, Catch::StartsWith("splinefig render: hair.toml:4: axes.series[0]: stroke_polyline: its outline would "
                                      "have about ") &&
                        Catch::Contains("over the limit of 2^26"));
  CHECK_FALSE(fs::exists(dir / "hair.png"));
  fs::remove_all(dir);
}

TEST_CASE("round caps on many dashes (dash work under its limit, outline past it) are refused naming the polyline") {
  // 5000 passes of 980 px, dashes [30, 30], round caps of a pen 40 px wide: 9e4 dashes of two
  // caps of about 500 vertices each.
  std::string spec = "[canvas]\nwidth = 1000\nheight = 1000\n[[polyline]]\nwidth = 40\ncap = \"round\"\ndash = [30, 30]\npoints = [";
  char buf[64];
  for (int i = 0; i < 5000; ++i) {
    std::snprintf(buf, sizeof buf, "%s[%d, %.3f]", i ? ", " : "", i % 2 ? 990 : 10, 10 + 0.19 * i);
    spec += buf;
  }
  spec += "]\n";
  check_refused("dash_caps", spec, "dash_caps.toml:4: polyline[0]: stroke_polyline: its outline would have about ");
}

TEST_CASE("the same series of 2000 hairpin turns draws") {
  const fs::path dir = scratch();
  write_file(dir / "hair.csv", hairpin_csv(2000));
  const Outcome o = render_spec(dir, "hair", hairpin_spec(2000, 2));
  INFO(o.seconds << " s: " << o.err);
  CHECK_FALSE(o.killed);
  CHECK(o.code == 0);
  CHECK(o.err.empty());
  CHECK(fs::exists(dir / "hair.png"));
  fs::remove_all(dir);
}
