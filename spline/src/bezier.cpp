// de Casteljau evaluation and splitting; cubic pieces in Bernstein form.
#include <splinefig/spline/bezier.hpp>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

namespace splinefig {

void de_casteljau(const Points& control, double t, std::span<double> out) {
  const std::size_t n = control.size();
  const std::size_t dim = static_cast<std::size_t>(control.dim);
  assert(n >= 1 && out.size() == dim);
  std::vector<double> w(control.coords);
  const double s = 1 - t;
  // Level r holds the n-r interpolants (1-t) w_k + t w_{k+1}, overwriting in place.
  for (std::size_t r = 1; r < n; ++r)
    for (std::size_t k = 0; k + r < n; ++k)
      for (std::size_t c = 0; c < dim; ++c) w[k * dim + c] = s * w[k * dim + c] + t * w[(k + 1) * dim + c];
  std::copy_n(w.begin(), dim, out.begin());
}

std::pair<Points, Points> split_bezier(const Points& control, double t) {
  const std::size_t n = control.size();
  const std::size_t dim = static_cast<std::size_t>(control.dim);
  assert(n >= 1);
  Points left(control.dim, n), right(control.dim, n);
  std::vector<double> w(control.coords);
  const double s = 1 - t;
  // The left half's control points are the first interpolant of each level, the right
  // half's the last one (read backwards).
  for (std::size_t r = 0; r < n; ++r) {
    if (r > 0)
      for (std::size_t k = 0; k + r < n; ++k)
        for (std::size_t c = 0; c < dim; ++c) w[k * dim + c] = s * w[k * dim + c] + t * w[(k + 1) * dim + c];
    const std::size_t last = n - 1 - r;
    for (std::size_t c = 0; c < dim; ++c) {
      left.coords[r * dim + c] = w[c];
      right.coords[last * dim + c] = w[last * dim + c];
    }
  }
  return {std::move(left), std::move(right)};
}

Points bezier_derivative(const Points& control) {
  const std::size_t n = control.size();
  const std::size_t dim = static_cast<std::size_t>(control.dim);
  assert(n >= 1);
  if (n == 1) return Points(control.dim, 1);
  Points d(control.dim, n - 1);
  const double deg = static_cast<double>(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k)
    for (std::size_t c = 0; c < dim; ++c)
      d.coords[k * dim + c] = deg * (control.coords[(k + 1) * dim + c] - control.coords[k * dim + c]);
  return d;
}

Points BezierSpline::piece(std::size_t i) const {
  assert(i < pieces());
  const std::size_t dim = static_cast<std::size_t>(points.dim);
  Points p(points.dim, 4);
  std::copy_n(points.coords.begin() + static_cast<std::ptrdiff_t>(3 * i * dim), 4 * dim, p.coords.begin());
  return p;
}

void evaluate(const BezierSpline& s, double t, int derivative, std::span<double> out) {
  const std::size_t n = s.pieces();
  const std::size_t dim = static_cast<std::size_t>(s.points.dim);
  assert(n >= 1 && out.size() == dim && derivative >= 0 && derivative <= 2);
  double fl = std::floor(t);
  if (fl < 0) fl = 0;
  if (fl > static_cast<double>(n - 1)) fl = static_cast<double>(n - 1);
  const std::size_t i = static_cast<std::size_t>(fl);
  const double u = t - fl, v = 1 - u;
  // Bernstein weights of the cubic and of its first two derivatives.
  double w[4];
  if (derivative == 0) {
    w[0] = v * v * v, w[1] = 3 * u * v * v, w[2] = 3 * u * u * v, w[3] = u * u * u;
  } else if (derivative == 1) {
    w[0] = -3 * v * v, w[1] = 3 * v * v - 6 * u * v, w[2] = 6 * u * v - 3 * u * u, w[3] = 3 * u * u;
  } else {
    w[0] = 6 * v, w[1] = 6 * u - 12 * v, w[2] = 6 * v - 12 * u, w[3] = 6 * u;
  }
  const double* p = s.points.coords.data() + 3 * i * dim;
  for (std::size_t c = 0; c < dim; ++c)
    out[c] = w[0] * p[c] + w[1] * p[dim + c] + w[2] * p[2 * dim + c] + w[3] * p[3 * dim + c];
}

}  // namespace splinefig
