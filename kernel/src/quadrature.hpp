#pragma once
// Internal: composite 16-point Gauss-Legendre quadrature, for the non-polynomial kernels.
#include <array>
#include <cmath>
#include <numbers>

namespace splinefig::detail {

// Nodes and weights on [-1, 1], by Newton's method on P_16.
struct GaussLegendre {
  static constexpr int n = 16;
  std::array<double, n> x{}, w{};
  GaussLegendre() {
    for (int i = 0; i < n; ++i) {
      double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1);
        const double dz = p1 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-16) break;
      }
      x[i] = z;
      w[i] = 2 / ((1 - z * z) * dp * dp);
    }
  }
};

// The integral of g over [a, b] with `panels` equal panels.
template <class G>
auto quadrature(G g, double a, double b, int panels) {
  static const GaussLegendre gl;
  const double h = (b - a) / panels;
  decltype(g(a)) sum{};
  for (int p = 0; p < panels; ++p) {
    const double mid = a + (p + 0.5) * h;
    for (int i = 0; i < GaussLegendre::n; ++i) sum += gl.w[i] * g(mid + 0.5 * h * gl.x[i]);
  }
  return sum * (0.5 * h);
}

// Panels for a smooth non-polynomial kernel over its support: 8 per unit of width.
inline int panels_for(double width) { return static_cast<int>(std::ceil(8 * width)); }

}  // namespace splinefig::detail
