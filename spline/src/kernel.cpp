// Kernel derivatives, integral and continuity class from the basis matrix's coefficients.
#include <splinefig/spline/kernel.hpp>

#include <algorithm>
#include <cmath>

namespace splinefig {
namespace {

double falling(int k, int m) {
  double f = 1;
  for (int t = 0; t < m; ++t) f *= k - t;
  return f;
}

// d^m/du^m of basis segment (column) c at u; 0 for a column outside 0..degree.
double column_derivative(const Basis& b, int c, double u, int m) {
  if (c < 0 || c > b.degree) return 0;
  const int n = b.degree;
  double v = 0;
  for (int r = 0; r <= n - m; ++r) v = v * u + falling(n - r, m) * b(r, c);
  return v;
}

}  // namespace

double kernel_derivative(const Basis& b, double s, int m) {
  const int n = b.degree, h = (n - 1) / 2;
  if (!(s >= h - n && s < h + 1)) return 0.0;
  // Column c covers [h-c, h-c+1) (basis.hpp).
  const int c = std::clamp(h - static_cast<int>(std::floor(s)), 0, n);
  return column_derivative(b, c, s - (h - c), m);
}

double kernel_integral(const Basis& b) {
  const int n = b.degree;
  double sum = 0;
  for (int r = 0; r <= n; ++r) {
    double row = 0;
    for (int c = 0; c <= n; ++c) row += b(r, c);
    sum += row / (n - r + 1);  // integral of u^(n-r) over [0,1]
  }
  return sum;
}

std::vector<double> kernel_jumps(const Basis& b, int m) {
  const int n = b.degree;
  std::vector<double> jumps;
  // Knot j = h - c is the left end of column c and the right end of column c+1; c = n gives
  // the support's left end, c = -1 its right end (columns outside 0..n are zero).
  for (int c = n; c >= -1; --c) {
    const double right = column_derivative(b, c, 0.0, m);
    const double left = column_derivative(b, c + 1, 1.0, m);
    jumps.push_back(right - left);
  }
  return jumps;
}

int kernel_continuity(const Basis& b, double tolerance) {
  const int n = b.degree;
  for (int m = 0; m <= n; ++m) {
    double scale = 0;
    for (int c = 0; c <= n; ++c)
      scale = std::max({scale, std::abs(column_derivative(b, c, 0.0, m)), std::abs(column_derivative(b, c, 1.0, m))});
    for (double j : kernel_jumps(b, m))
      if (std::abs(j) > tolerance * std::max(scale, 1e-300)) return m - 1;
  }
  return n;
}

}  // namespace splinefig
