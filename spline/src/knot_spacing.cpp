// Non-uniformly spaced Catmull-Rom pieces in Hermite form.
#include <splinefig/spline/knot_spacing.hpp>
#include <splinefig/spline/curve.hpp>

#include "open_cubic_sampling.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace splinefig {

double spacing_exponent(KnotSpacing s) {
  switch (s) {
    case KnotSpacing::uniform: return 0.0;
    case KnotSpacing::chordal: return 1.0;
    case KnotSpacing::centripetal: return 0.5;
  }
  return 0.0;
}

std::optional<KnotSpacing> parse_knot_spacing(std::string_view name) {
  if (name == "uniform") return KnotSpacing::uniform;
  if (name == "chordal") return KnotSpacing::chordal;
  if (name == "centripetal") return KnotSpacing::centripetal;
  return std::nullopt;
}

namespace {

// |knot j - knot j-1| without overflow or underflow of the squares (infinite only beyond the
// range of a double).
double distance(const Points& knots, std::size_t j) {
  const std::size_t dim = static_cast<std::size_t>(knots.dim);
  double scale = 0;
  for (std::size_t c = 0; c < dim; ++c)
    scale = std::max(scale, std::abs(knots.coords[j * dim + c] - knots.coords[(j - 1) * dim + c]));
  if (!(scale > 0) || !std::isfinite(scale)) return scale;
  double s2 = 0;
  for (std::size_t c = 0; c < dim; ++c) {
    const double d = (knots.coords[j * dim + c] - knots.coords[(j - 1) * dim + c]) / scale;
    s2 += d * d;
  }
  return scale * std::sqrt(s2);
}

}  // namespace

std::vector<double> knot_parameters(const Points& knots, double alpha) {
  const std::size_t n = knots.size(), dim = static_cast<std::size_t>(knots.dim);
  std::vector<double> tau(n, 0.0);
  for (std::size_t j = 1; j < n; ++j) {
    double d2 = 0;
    for (std::size_t c = 0; c < dim; ++c) {
      const double d = knots.coords[j * dim + c] - knots.coords[(j - 1) * dim + c];
      d2 += d * d;
    }
    // |d|^alpha = (|d|^2)^(alpha/2); pow(0, 0) = 1 keeps uniform spacing for coincident knots.
    // Where |d|^2 overflows or underflows (|d| beyond about 1e154 or below 1e-154) |d| is
    // taken in scaled form instead (which also gives 0 for coincident knots).
    const bool in_range = std::isfinite(d2) && d2 >= std::numeric_limits<double>::min();
    tau[j] = tau[j - 1] + (in_range ? std::pow(d2, alpha / 2) : std::pow(distance(knots, j), alpha));
  }
  return tau;
}

namespace {

// (b - a) / h, with 0/0 (coincident knots, zero interval) read as 0.
inline double quotient(double diff, double h) { return h > 0 ? diff / h : 0.0; }

}  // namespace

void spaced_catmull_rom(const Points& knots, const std::vector<double>& tau, std::size_t i, double u,
                        int derivative, std::span<double> out) {
  const std::size_t dim = static_cast<std::size_t>(knots.dim);
  assert(i >= 1 && i + 2 < knots.size() && out.size() == dim && derivative >= 0 && derivative <= 2);
  const double h0 = tau[i] - tau[i - 1], h1 = tau[i + 1] - tau[i], h2 = tau[i + 2] - tau[i + 1];
  if (!(h1 > 0)) {
    for (std::size_t c = 0; c < dim; ++c) out[c] = derivative == 0 ? knots.coords[i * dim + c] : 0.0;
    return;
  }
  // Cubic Hermite basis in u and its u-derivatives; tangents scaled to u by h1.
  double w[4];
  const double u2 = u * u, u3 = u2 * u;
  if (derivative == 0) {
    w[0] = 2 * u3 - 3 * u2 + 1, w[1] = -2 * u3 + 3 * u2, w[2] = u3 - 2 * u2 + u, w[3] = u3 - u2;
  } else if (derivative == 1) {
    w[0] = 6 * u2 - 6 * u, w[1] = -6 * u2 + 6 * u, w[2] = 3 * u2 - 4 * u + 1, w[3] = 3 * u2 - 2 * u;
  } else {
    w[0] = 12 * u - 6, w[1] = -12 * u + 6, w[2] = 6 * u - 4, w[3] = 6 * u - 2;
  }
  const double scale = derivative == 0 ? 1.0 : (derivative == 1 ? 1 / h1 : 1 / (h1 * h1));
  const double* x0 = knots.coords.data() + (i - 1) * dim;
  const double* x1 = x0 + dim;
  const double* x2 = x1 + dim;
  const double* x3 = x2 + dim;
  for (std::size_t c = 0; c < dim; ++c) {
    const double v1 = quotient(x1[c] - x0[c], h0) - quotient(x2[c] - x0[c], h0 + h1) + (x2[c] - x1[c]) / h1;
    const double v2 = (x2[c] - x1[c]) / h1 - quotient(x3[c] - x1[c], h1 + h2) + quotient(x3[c] - x2[c], h2);
    out[c] = scale * (w[0] * x1[c] + w[1] * x2[c] + h1 * (w[2] * v1 + w[3] * v2));
  }
}

Points spaced_catmull_rom_curve(const Points& knots, double alpha, int grain, int derivative) {
  const std::vector<double> tau = knot_parameters(knots, alpha);
  for (std::size_t j = 1; j < tau.size(); ++j)
    if (!std::isfinite(tau[j]))
      throw CurveError("the knot parameters overflow at knot " + std::to_string(j + 1) +
                                  ": the knots are too far apart for this spacing");
  return detail::sample_open_cubic("Catmull-Rom", knots.dim, knots.size(), grain,
                                   [&](std::size_t i, double u, std::span<double> out) {
                                     spaced_catmull_rom(knots, tau, i, u, derivative, out);
                                   });
}

Points sample_spaced(const Curve& c, double alpha, int grain, int derivative) {
  const bool catmull_rom = c.basis.degree == 3 && c.basis.family == "cardinal" && c.basis(2, 0) == -0.5 &&
                           c.basis(2, 2) == 0.5;
  if (!catmull_rom)
    throw CurveError("knot spacing applies to the Catmull-Rom basis only, not " + c.basis.spec);
  return spaced_catmull_rom_curve(c.control, alpha, grain, derivative);
}

}  // namespace splinefig
