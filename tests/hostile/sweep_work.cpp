// A polyline whose outline crosses itself past the sweep's work limit is refused at once, naming
// the spec, the item and the bound, instead of being swept for minutes.
#include "hostile.hpp"

#include <cstdio>
#include <random>

using namespace splinefig::hostile;

TEST_CASE("30000 random points on 1024^2 (about 4e8 crossings, minutes of sweeping) are refused at once") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1024);
  std::string spec = "[canvas]\nwidth = 1024\nheight = 1024\n[[polyline]]\nwidth = 1\npoints = [";
  char buf[64];
  for (int i = 0; i < 30000; ++i) {
    std::snprintf(buf, sizeof buf, "%s[%.3f, %.3f]", i ? ", " : "", u(rng), u(rng));
    spec += buf;
  }
  spec += "]\n";
  check_refused("dense", spec, "dense.toml: item 1 (stroked polyline): its outline crosses itself at least ");
}
