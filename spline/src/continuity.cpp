// Parametric and geometric continuity at the joints of a curve (see continuity.hpp).
#include <splinefig/spline/continuity.hpp>
#include <splinefig/spline/segment.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace splinefig {
namespace {

double norm(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

double distance(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

// K = (X'' - (X''.T) T) / |X'|^2 with T = X'/|X'|: the curvature vector, any dimension.
std::vector<double> curvature_vector(const std::vector<double>& d1, const std::vector<double>& d2) {
  const double v2 = dot(d1, d1);
  std::vector<double> k(d1.size(), std::numeric_limits<double>::quiet_NaN());
  if (!(v2 > 0)) return k;
  const double along = dot(d2, d1) / v2;
  for (size_t i = 0; i < k.size(); ++i) k[i] = (d2[i] - along * d1[i]) / v2;
  return k;
}

void piece_derivatives(const Curve& c, std::size_t piece, double u, std::vector<double> (&out)[3]) {
  std::vector<double> a(static_cast<size_t>(c.basis.order() * c.dim()));
  piece_coefficients(c, piece, a);
  for (int m = 0; m < 3; ++m) {
    out[m].assign(static_cast<size_t>(c.dim()), 0.0);
    if (m <= c.degree()) segment_point(a, c.degree(), c.dim(), u, m, out[m]);
  }
}

}  // namespace

std::vector<Joint> joints(const Curve& c) {
  std::vector<Joint> out;
  const std::size_t n = c.segments();
  const std::size_t count = c.ends == Ends::closed ? n : n - 1;
  for (std::size_t j = 0; j < count; ++j) {
    const std::size_t before = j, after = (j + 1) % n;
    Joint J{};
    J.t = static_cast<double>(j + 1);
    piece_derivatives(c, before, 1.0, J.left);
    piece_derivatives(c, after, 0.0, J.right);
    for (int m = 0; m < 3; ++m) J.jump[m] = distance(J.left[m], J.right[m]);
    const double vl = norm(J.left[1]), vr = norm(J.right[1]);
    J.velocity_ratio = vr / vl;
    // 2 atan2(|a - b|, |a + b|) for unit a, b: accurate for small angles, unlike acos.
    J.tangent_angle = std::numeric_limits<double>::quiet_NaN();
    if (vl > 0 && vr > 0) {
      std::vector<double> diff(J.left[1].size()), sum(J.left[1].size());
      for (size_t d = 0; d < diff.size(); ++d) {
        diff[d] = J.right[1][d] / vr - J.left[1][d] / vl;
        sum[d] = J.right[1][d] / vr + J.left[1][d] / vl;
      }
      J.tangent_angle = 2 * std::atan2(norm(diff), norm(sum));
    }
    J.curvature_jump = distance(curvature_vector(J.left[1], J.left[2]), curvature_vector(J.right[1], J.right[2]));
    out.push_back(std::move(J));
  }
  return out;
}

int parametric_continuity(const Curve& c, double tolerance) {
  const std::vector<Joint> js = joints(c);
  double knot_size = 0;
  for (double x : c.control.coords) knot_size = std::max(knot_size, std::abs(x));
  for (int m = 0; m < 3; ++m) {
    double scale = m == 0 ? knot_size : 0;
    for (const Joint& J : js) scale = std::max({scale, norm(J.left[m]), norm(J.right[m])});
    for (const Joint& J : js)
      if (J.jump[m] > tolerance * std::max(scale, 1e-300)) return m - 1;
  }
  return 2;
}

int geometric_continuity(const Curve& c, double tolerance) {
  if (parametric_continuity(c, tolerance) < 0) return -1;
  const std::vector<Joint> js = joints(c);
  for (const Joint& J : js)
    if (!(J.tangent_angle <= tolerance)) return 0;  // NaN (a zero velocity) fails too
  double scale = 0;
  for (const Joint& J : js)
    for (const auto* side : {&J.left, &J.right})
      scale = std::max(scale, norm(curvature_vector((*side)[1], (*side)[2])));
  for (const Joint& J : js)
    if (!(J.curvature_jump <= tolerance * std::max(scale, 1e-300))) return 1;
  return 2;
}

double beta_constraint_residual(const Curve& c, double b1, double b2) {
  double worst = 0;
  for (const Joint& J : joints(c)) {
    const auto& l = J.left;
    const auto& r = J.right;
    const double s1 = std::max({norm(l[1]), norm(r[1]), 1e-300});
    const double s2 = std::max({norm(l[2]), norm(r[2]), s1});
    for (size_t d = 0; d < l[1].size(); ++d) {
      worst = std::max(worst, std::abs(r[1][d] - b1 * l[1][d]) / s1);
      worst = std::max(worst, std::abs(r[2][d] - (b1 * b1 * l[2][d] + b2 * l[1][d])) / s2);
    }
  }
  return worst;
}

}  // namespace splinefig
