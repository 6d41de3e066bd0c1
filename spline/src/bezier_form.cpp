// Change of basis from the power form of a piece to its Bezier control points.
#include <splinefig/spline/bezier_form.hpp>
#include <splinefig/spline/curve.hpp>

#include <splinefig/spline/segment.hpp>

#include <stdexcept>
#include <string>

namespace splinefig {
namespace {

double binomial(int n, int k) {
  double r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

}  // namespace

Points bezier_from_power(std::span<const double> ascending, int degree, int dim) {
  if (degree < 0 || dim < 1 || ascending.size() != static_cast<std::size_t>((degree + 1) * dim))
    throw CurveError("bezier_from_power: need (degree+1)*dim coefficients");
  Points out(dim, static_cast<std::size_t>(degree + 1));
  for (int j = 0; j <= degree; ++j)
    for (int k = 0; k <= j; ++k) {
      const double w = binomial(j, k) / binomial(degree, k);
      for (int d = 0; d < dim; ++d) out.coords[j * dim + d] += w * ascending[k * dim + d];
    }
  return out;
}

std::vector<double> bezier_matrix(const Basis& b) {
  const int n = b.degree, m = b.order();
  std::vector<double> out(static_cast<std::size_t>(m * m));
  // Column c of M (rows u^n .. 1) is control point c's polynomial; its Bezier points are column
  // c of M_B^-1 M.
  std::vector<double> asc(static_cast<std::size_t>(m));
  for (int c = 0; c < m; ++c) {
    for (int r = 0; r < m; ++r) asc[static_cast<std::size_t>(n - r)] = b(r, c);
    const Points col = bezier_from_power(asc, n, 1);
    for (int j = 0; j < m; ++j) out[static_cast<std::size_t>(j * m + c)] = col.coords[static_cast<std::size_t>(j)];
  }
  return out;
}

Points piece_bezier(const Curve& c, std::size_t i) {
  if (i >= c.segments()) throw std::out_of_range("piece_bezier: piece " + std::to_string(i) + " of " + std::to_string(c.segments()));
  const int n = c.degree(), dim = c.dim();
  std::vector<double> a(static_cast<std::size_t>((n + 1) * dim));
  segment_coefficients(c.basis, c.piece_control(i), dim, a);  // a[r*dim+d] multiplies u^(n-r)
  std::vector<double> asc(a.size());
  for (int r = 0; r <= n; ++r)
    for (int d = 0; d < dim; ++d) asc[static_cast<std::size_t>((n - r) * dim + d)] = a[static_cast<std::size_t>(r * dim + d)];
  return bezier_from_power(asc, n, dim);
}

Points kernel_piece_bezier(const Basis& b, int piece, double u0, double u1, double scale) {
  const int n = b.degree;
  if (piece < 0 || piece > n) throw std::out_of_range("kernel_piece_bezier: piece " + std::to_string(piece));
  const Support sup = kernel_support(b);
  const int col = n - piece;  // column c is the piece on [h - c, h - c + 1)
  // y(u) = scale * sum_r M(r, col) u^(n-r), then u = u0 + (u1 - u0) v: the ascending
  // coefficients of v by the binomial expansion of (u0 + L v)^k.
  std::vector<double> yu(static_cast<std::size_t>(n + 1));
  for (int r = 0; r <= n; ++r) yu[static_cast<std::size_t>(n - r)] = scale * b(r, col);
  const double L = u1 - u0;
  std::vector<double> asc(static_cast<std::size_t>(2 * (n + 1)), 0.0);
  for (int k = 0; k <= n; ++k) {
    double lk = 1;  // L^j
    for (int j = 0; j <= k; ++j, lk *= L) {
      double u0p = 1;  // u0^(k-j)
      for (int q = 0; q < k - j; ++q) u0p *= u0;
      asc[static_cast<std::size_t>(2 * j + 1)] += yu[static_cast<std::size_t>(k)] * binomial(k, j) * u0p * lk;
    }
  }
  asc[0] = sup.lo + piece + u0;  // x(v) = lo + p + u0 + L v
  if (n >= 1) asc[2] = L;
  return bezier_from_power(asc, n, 2);
}

}  // namespace splinefig
