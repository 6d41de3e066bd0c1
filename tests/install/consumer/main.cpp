// A user's program: the Catmull-Rom kernel at 0 is 1 and the B-spline's is 2/3.
#include <splinefig/spline/basis.hpp>
#include <splinefig/version.hpp>

#include <cmath>
#include <cstdio>

int main() {
  const double c = splinefig::kernel(splinefig::parse_basis("catmull-rom"), 0.0);
  const double b = splinefig::kernel(splinefig::parse_basis("bspline"), 0.0);
  std::printf("splinefig %s: catmull-rom k(0) = %.17g, bspline k(0) = %.17g\n", SPLINEFIG_VERSION, c, b);
  return (std::fabs(c - 1.0) < 1e-15 && std::fabs(b - 2.0 / 3.0) < 1e-15) ? 0 : 1;
}
