// Horner evaluation of one spline piece and of the basis segments.
#include <splinefig/spline/segment.hpp>

#include <cassert>

namespace splinefig {
namespace {

// (m)(m-1)...(m-k+1): the factor d^k/du^k brings down from u^m.
double falling(int m, int k) {
  double f = 1;
  for (int t = 0; t < k; ++t) f *= m - t;
  return f;
}

}  // namespace

void segment_coefficients(const Basis& b, std::span<const double> control, int dim,
                          std::span<double> a) {
  const int o = b.order();
  assert(static_cast<int>(control.size()) >= o * dim && static_cast<int>(a.size()) >= o * dim);
  for (int r = 0; r < o; ++r)
    for (int d = 0; d < dim; ++d) {
      double s = 0;
      for (int c = 0; c < o; ++c) s += b(r, c) * control[static_cast<size_t>(c * dim + d)];
      a[static_cast<size_t>(r * dim + d)] = s;
    }
}

void segment_point(std::span<const double> a, int degree, int dim, double u, int derivative,
                   std::span<double> out) {
  assert(static_cast<int>(out.size()) >= dim && derivative >= 0);
  for (int d = 0; d < dim; ++d) out[static_cast<size_t>(d)] = 0;
  // Row r multiplies u^(degree-r); rows with degree-r < derivative vanish.
  for (int r = 0; r <= degree - derivative; ++r) {
    const double f = falling(degree - r, derivative);
    for (int d = 0; d < dim; ++d) {
      double& v = out[static_cast<size_t>(d)];
      v = v * u + f * a[static_cast<size_t>(r * dim + d)];
    }
  }
}

void basis_weights(const Basis& b, double u, int derivative, std::span<double> w) {
  const int n = b.degree;
  assert(static_cast<int>(w.size()) >= n + 1);
  for (int c = 0; c <= n; ++c) {
    double v = 0;
    for (int r = 0; r <= n - derivative; ++r) v = v * u + falling(n - r, derivative) * b(r, c);
    w[static_cast<size_t>(c)] = v;
  }
}

}  // namespace splinefig
