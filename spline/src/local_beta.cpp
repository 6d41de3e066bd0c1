// Beta-spline weights as functions of u through blended shape parameters, differentiated
// exactly by second-order forward mode (a value with its first two u-derivatives).
#include <splinefig/spline/local_beta.hpp>
#include <splinefig/spline/curve.hpp>

#include "open_cubic_sampling.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>

namespace splinefig {
namespace {

// f, f', f'' of a function of u; products and quotients by the Leibniz rule.
struct Jet {
  double v = 0, d1 = 0, d2 = 0;
};
Jet operator+(Jet a, Jet b) { return {a.v + b.v, a.d1 + b.d1, a.d2 + b.d2}; }
Jet operator-(Jet a, Jet b) { return {a.v - b.v, a.d1 - b.d1, a.d2 - b.d2}; }
Jet operator*(double k, Jet a) { return {k * a.v, k * a.d1, k * a.d2}; }
Jet operator+(Jet a, double k) { return {a.v + k, a.d1, a.d2}; }
Jet operator*(Jet a, Jet b) { return {a.v * b.v, a.d1 * b.v + a.v * b.d1, a.d2 * b.v + 2 * a.d1 * b.d1 + a.v * b.d2}; }
Jet operator/(Jet a, Jet b) {
  Jet q;
  q.v = a.v / b.v;
  q.d1 = (a.d1 - q.v * b.d1) / b.v;
  q.d2 = (a.d2 - 2 * q.d1 * b.d1 - q.v * b.d2) / b.v;
  return q;
}

double denominator(double b1, double b2) { return b2 + 2 * b1 * b1 * b1 + 4 * b1 * b1 + 4 * b1 + 2; }

// Weights of x_{i-1}, x_i, x_{i+1}, x_{i+2}: [u^3 u^2 u 1] times the columns of Barsky's
// B_{b1,b2} (the memo's matrix), all as jets in u.
void beta_weights(Jet b1, Jet b2, Jet u, Jet w[4]) {
  const Jet s2 = b1 * b1, s3 = s2 * b1;
  const Jet d = b2 + 2.0 * s3 + 4.0 * s2 + 4.0 * b1 + 2.0;
  const Jet u2 = u * u, u3 = u2 * u;
  const Jet one{1, 0, 0};
  // Columns of the memo's B_{b1,b2} (times d), rows u^3, u^2, u, 1.
  const Jet c0 = (-2.0 * s3) * u3 + (6.0 * s3) * u2 + (-6.0 * s3) * u + 2.0 * s3;
  const Jet c1 = (2.0 * (b2 + s3 + s2 + b1)) * u3 + (-3.0 * (b2 + 2.0 * s3 + 2.0 * s2)) * u2 +
                 (6.0 * (s3 - b1)) * u + (b2 + 4.0 * (s2 + b1));
  const Jet c2 = (-2.0 * (b2 + s2 + b1 + 1.0)) * u3 + (3.0 * (b2 + 2.0 * s2)) * u2 + (6.0 * b1) * u + 2.0 * one;
  const Jet c3 = 2.0 * u3;
  w[0] = c0 / d, w[1] = c1 / d, w[2] = c2 / d, w[3] = c3 / d;
}

}  // namespace

double quintic_blend(double u, int derivative) {
  switch (derivative) {
    case 0: return u * u * u * (10 + u * (-15 + 6 * u));
    case 1: return 30 * u * u * (1 + u * (-2 + u));
    case 2: return 60 * u * (1 + u * (-3 + 2 * u));
  }
  return 0;
}

void validate_local_betas(const Points& knots, std::span<const ShapeParameters> betas) {
  if (betas.size() != knots.size())
    throw CurveError("local betas: " + std::to_string(betas.size()) + " (b1, b2) pairs for " +
                                std::to_string(knots.size()) + " knots (one per knot)");
  for (std::size_t j = 0; j < betas.size(); ++j)
    if (!std::isfinite(betas[j].b1) || !std::isfinite(betas[j].b2))
      throw CurveError("local betas: knot " + std::to_string(j) + " has a non-finite b1 or b2");
  for (std::size_t j = 0; j + 1 < betas.size(); ++j) {
    const double b1 = std::min(betas[j].b1, betas[j + 1].b1), b2 = std::min(betas[j].b2, betas[j + 1].b2);
    const double d = denominator(b1, b2);
    // d grows with b1 >= 0 and b2: its largest value between the knots is at the larger pair.
    if (!std::isfinite(denominator(std::max(betas[j].b1, betas[j + 1].b1), std::max(betas[j].b2, betas[j + 1].b2))))
      throw CurveError("local betas: between knots " + std::to_string(j) + " and " + std::to_string(j + 1) +
                                  " b1 or b2 is too large: the denominator d overflows");
    if (!(d > 0))
      throw CurveError("local betas: between knots " + std::to_string(j) + " and " + std::to_string(j + 1) +
                                  " the Beta-spline denominator d = b2 + 2b1^3 + 4b1^2 + 4b1 + 2 can reach 0 "
                                  "(raise b1 or b2)");
  }
  // b1 is the ratio of the velocities after and before a joint: below 0 the curve reverses there.
  for (std::size_t j = 0; j < betas.size(); ++j)
    if (betas[j].b1 < 0)
      throw CurveError("local betas: knot " + std::to_string(j) + " has a negative b1 (b1 >= 0)");
}

void local_beta_point(const Points& knots, std::span<const ShapeParameters> betas, std::size_t i, double u,
                      int derivative, std::span<double> out) {
  const std::size_t dim = static_cast<std::size_t>(knots.dim);
  assert(i >= 1 && i + 2 < knots.size() && betas.size() == knots.size() && out.size() == dim);
  assert(derivative >= 0 && derivative <= 2);
  const Jet h{quintic_blend(u, 0), quintic_blend(u, 1), quintic_blend(u, 2)};
  const ShapeParameters a = betas[i], b = betas[i + 1];
  const Jet b1 = (b.b1 - a.b1) * h + a.b1;
  const Jet b2 = (b.b2 - a.b2) * h + a.b2;
  Jet w[4];
  beta_weights(b1, b2, Jet{u, 1, 0}, w);
  const double* x = knots.coords.data() + (i - 1) * dim;
  for (std::size_t c = 0; c < dim; ++c) {
    double sum = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      const double wk = derivative == 0 ? w[k].v : (derivative == 1 ? w[k].d1 : w[k].d2);
      sum += wk * x[k * dim + c];
    }
    out[c] = sum;
  }
}

Points local_beta_curve(const Points& knots, std::span<const ShapeParameters> betas, int grain, int derivative) {
  validate_local_betas(knots, betas);
  return detail::sample_open_cubic("Beta-spline", knots.dim, knots.size(), grain,
                                   [&](std::size_t i, double u, std::span<double> out) {
                                     local_beta_point(knots, betas, i, u, derivative, out);
                                   });
}

std::vector<ShapeParameters> extend_betas(std::span<const ShapeParameters> betas, Ends ends) {
  const std::size_t n = betas.size();
  std::vector<ShapeParameters> out;
  if (n == 0) return out;
  switch (ends) {
    case Ends::open:
      out.assign(betas.begin(), betas.end());
      break;
    case Ends::doubled:
      out.push_back(betas.front());
      out.insert(out.end(), betas.begin(), betas.end());
      out.push_back(betas.back());
      break;
    case Ends::closed:
      // As make_curve wraps a cubic's knots: the last in front, the first two behind.
      for (std::size_t j = 0; j < n + 3; ++j) out.push_back(betas[(j + 2 * n - 1) % n]);
      break;
  }
  return out;
}

Points sample_local_betas(const Curve& c, std::span<const ShapeParameters> betas, int grain, int derivative) {
  if (c.degree() != 3) throw CurveError("local betas need a cubic curve, not " + c.basis.spec);
  if (betas.size() != c.knot_count)
    throw CurveError("local betas: " + std::to_string(betas.size()) + " (b1, b2) pairs for " +
                                std::to_string(c.knot_count) + " knots (one per knot)");
  const std::vector<ShapeParameters> all = extend_betas(betas, c.ends);
  Points out = local_beta_curve(c.control, all, grain, derivative);
  // A closed curve ends exactly where it starts (as sample() does for the uniform bases).
  if (c.ends == Ends::closed && derivative == 0)
    std::copy_n(out.coords.begin(), c.dim(), out.coords.end() - c.dim());
  return out;
}

}  // namespace splinefig
