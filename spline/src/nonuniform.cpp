// Cox-de Boor basis functions, de Boor's algorithm, derivative curves and knot insertion.
#include <splinefig/spline/nonuniform.hpp>
#include <splinefig/spline/curve.hpp>

#include "weight_table.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>

namespace splinefig {

void validate(const BSplineCurve& c) {
  const auto count = c.control.size();
  if (c.degree < 0) throw CurveError("B-spline degree must be >= 0, got " + std::to_string(c.degree));
  const auto p = static_cast<std::size_t>(c.degree);
  if (c.control.dim < 1 || count < p + 1)
    throw CurveError("a degree-" + std::to_string(p) + " B-spline needs at least " +
                                std::to_string(p + 1) + " control points, got " + std::to_string(count));
  if (c.knots.size() != count + p + 1)
    throw CurveError("a degree-" + std::to_string(p) + " B-spline with " + std::to_string(count) +
                                " control points needs " + std::to_string(count + p + 1) + " knots, got " +
                                std::to_string(c.knots.size()));
  for (std::size_t i = 0; i < c.knots.size(); ++i) {
    if (!std::isfinite(c.knots[i])) throw CurveError("knot " + std::to_string(i) + " is not finite");
    if (i > 0 && c.knots[i] < c.knots[i - 1])
      throw CurveError("knot " + std::to_string(i) + " is smaller than knot " + std::to_string(i - 1));
  }
  if (!(c.t_max() > c.t_min()))
    throw CurveError("the knot vector leaves the curve an empty domain (knot p = knot count)");
}

std::vector<double> uniform_knots(std::size_t count, int degree) {
  std::vector<double> k(count + static_cast<std::size_t>(degree) + 1);
  for (std::size_t i = 0; i < k.size(); ++i) k[i] = static_cast<double>(i);
  return k;
}

std::vector<double> clamped_knots(std::size_t count, int degree) {
  const auto p = static_cast<std::size_t>(degree);
  assert(count >= p + 1);
  std::vector<double> k(count + p + 1);
  const double last = static_cast<double>(count - p);
  for (std::size_t i = 0; i < k.size(); ++i)
    k[i] = i <= p ? 0.0 : (i >= count ? last : static_cast<double>(i - p));
  return k;
}

std::size_t find_span(const std::vector<double>& knots, int degree, std::size_t count, double t) {
  const auto p = static_cast<std::size_t>(degree);
  if (!(t < knots[count])) {
    std::size_t s = count - 1;
    while (s > p && knots[s] == knots[s + 1]) --s;
    return s;
  }
  if (!(t > knots[p])) {
    std::size_t s = p;
    while (s + 1 < count && knots[s] == knots[s + 1]) ++s;
    return s;
  }
  // First knot in (t_p, t_count] greater than t; the span starts one before it.
  const auto first = knots.begin() + static_cast<std::ptrdiff_t>(p);
  const auto last = knots.begin() + static_cast<std::ptrdiff_t>(count) + 1;
  return static_cast<std::size_t>(std::upper_bound(first, last, t) - knots.begin()) - 1;
}

void basis_functions(const std::vector<double>& knots, int degree, std::size_t span, double t,
                     std::span<double> out) {
  const auto p = static_cast<std::size_t>(degree);
  assert(out.size() == p + 1);
  // Raise the degree one step at a time: at step j the j+1 functions of degree j on the span
  // are combined with the weights (t - t_i)/(t_{i+j} - t_i) of the recursion; the
  // denominators are lengths of intervals containing the non-empty span, never 0.
  std::array<double, 33> left_small, right_small;  // no need to clear: written before read
  std::vector<double> left_big, right_big;
  double* left = left_small.data();
  double* right = right_small.data();
  if (p + 1 > left_small.size()) {
    left_big.resize(p + 1), right_big.resize(p + 1);
    left = left_big.data(), right = right_big.data();
  }
  out[0] = 1;
  for (std::size_t j = 1; j <= p; ++j) {
    left[j] = t - knots[span + 1 - j];
    right[j] = knots[span + j] - t;
    double saved = 0;
    for (std::size_t r = 0; r < j; ++r) {
      const double temp = out[r] / (right[r + 1] + left[j - r]);
      out[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    out[j] = saved;
  }
}

double cox_de_boor(const std::vector<double>& knots, int degree, std::size_t i, double t) {
  if (degree == 0) return knots[i] <= t && t < knots[i + 1] ? 1.0 : 0.0;
  const auto p = static_cast<std::size_t>(degree);
  double v = 0;
  const double a = knots[i + p] - knots[i];
  if (a != 0) v += (t - knots[i]) / a * cox_de_boor(knots, degree - 1, i, t);
  const double b = knots[i + p + 1] - knots[i + 1];
  if (b != 0) v += (knots[i + p + 1] - t) / b * cox_de_boor(knots, degree - 1, i + 1, t);
  return v;
}

void de_boor(const BSplineCurve& c, double t, std::span<double> out) {
  const auto p = static_cast<std::size_t>(c.degree);
  const auto dim = static_cast<std::size_t>(c.control.dim);
  const std::size_t count = c.control.size();
  assert(out.size() == dim);
  const std::size_t s = find_span(c.knots, c.degree, count, t);
  const std::vector<double>& k = c.knots;
  // d_j = P_{s-p+j}; level r replaces d_j (j = p..r) by the point at t on the segment
  // d_{j-1} d_j, whose knots are t_{s-p+j} and t_{s+1+j-r}.
  std::array<double, 64> small;  // written before read
  std::vector<double> big;
  double* d = small.data();
  if ((p + 1) * dim > small.size()) {
    big.resize((p + 1) * dim);
    d = big.data();
  }
  std::copy_n(c.control.coords.begin() + static_cast<std::ptrdiff_t>((s - p) * dim), (p + 1) * dim, d);
  for (std::size_t r = 1; r <= p; ++r)
    for (std::size_t j = p; j >= r; --j) {
      const double lo = k[s - p + j], hi = k[s + 1 + j - r];
      const double a = (t - lo) / (hi - lo);
      for (std::size_t q = 0; q < dim; ++q) d[j * dim + q] = (1 - a) * d[(j - 1) * dim + q] + a * d[j * dim + q];
    }
  std::copy_n(d + p * dim, dim, out.begin());
}

BSplineCurve derivative(const BSplineCurve& c) {
  const auto dim = static_cast<std::size_t>(c.control.dim);
  const std::size_t count = c.control.size();
  if (c.degree == 0) return BSplineCurve{0, c.knots, Points(c.control.dim, count)};
  const auto p = static_cast<std::size_t>(c.degree);
  BSplineCurve d{c.degree - 1, std::vector<double>(c.knots.begin() + 1, c.knots.end() - 1),
                 Points(c.control.dim, count - 1)};
  for (std::size_t i = 0; i + 1 < count; ++i) {
    const double h = c.knots[i + p + 1] - c.knots[i + 1];
    const double f = h > 0 ? static_cast<double>(p) / h : 0.0;
    for (std::size_t q = 0; q < dim; ++q)
      d.control.coords[i * dim + q] = f * (c.control.coords[(i + 1) * dim + q] - c.control.coords[i * dim + q]);
  }
  return d;
}

void evaluate(const BSplineCurve& c, double t, int derivative_order, std::span<double> out) {
  assert(derivative_order >= 0);
  if (derivative_order == 0) return de_boor(c, t, out);
  if (derivative_order > c.degree) {
    std::fill(out.begin(), out.end(), 0.0);
    return;
  }
  BSplineCurve d = derivative(c);
  for (int k = 1; k < derivative_order; ++k) d = derivative(d);
  // The derivative curve lives on the same domain [t_p, t_count] (its knots lost one at each end).
  de_boor(d, t, out);
}

Points sample(const BSplineCurve& c, int grain) {
  if (grain < 1) throw CurveError("grain must be at least 1, got " + std::to_string(grain));
  const auto p = static_cast<std::size_t>(c.degree);
  const auto dim = static_cast<std::size_t>(c.control.dim);
  const std::size_t count = c.control.size(), g = static_cast<std::size_t>(grain);
  const std::vector<double>& k = c.knots;
  std::size_t spans = 0;
  for (std::size_t s = p; s < count; ++s) spans += k[s + 1] > k[s];
  Points out(c.control.dim, spans * g + 1);
  double* o = out.coords.data();
  // E[i*K + j*dim + q] = N_{s-p+i}(t_j) for the grain parameters t_j of span s, repeated for
  // each coordinate q (K = grain*dim). The basis functions on a span depend only on the
  // differences of the 2p knots around it, so a span shaped like the one before (every span of
  // a uniform knot vector) reuses its table.
  const std::size_t K = g * dim;
  std::vector<double> E((p + 1) * K), w(p + 1), Q((p + 1) * 4 * dim), shape, prev_shape;
  std::size_t last = p;
  for (std::size_t s = p; s < count; ++s) {
    const double a = k[s], b = k[s + 1];
    if (!(b > a)) continue;
    last = s;
    shape.assign(k.begin() + static_cast<std::ptrdiff_t>(s + 1 - p), k.begin() + static_cast<std::ptrdiff_t>(s + p + 1));
    for (double& x : shape) x -= a;
    if (shape != prev_shape) {
      for (std::size_t j = 0; j < g; ++j) {
        basis_functions(k, c.degree, s, a + (b - a) * static_cast<double>(j) / static_cast<double>(g), w);
        for (std::size_t i = 0; i <= p; ++i)
          for (std::size_t q = 0; q < dim; ++q) E[i * K + j * dim + q] = w[i];
      }
      prev_shape.swap(shape);
    }
    const double* P = c.control.coords.data() + (s - p) * dim;
    detail::apply_span_weights(E.data(), K, P, p + 1, dim, Q.data(), o);
    o += K;
  }
  std::vector<double> N(p + 1);
  basis_functions(k, c.degree, last, k[last + 1], N);
  const double* P = c.control.coords.data() + (last - p) * dim;
  for (std::size_t q = 0; q < dim; ++q) {
    double v = 0;
    for (std::size_t i = 0; i <= p; ++i) v += N[i] * P[i * dim + q];
    o[q] = v;
  }
  return out;
}

BSplineCurve insert_knot(const BSplineCurve& c, double t) {
  const auto p = static_cast<std::size_t>(c.degree);
  const auto dim = static_cast<std::size_t>(c.control.dim);
  const std::size_t count = c.control.size();
  const std::size_t s = find_span(c.knots, c.degree, count, t);
  BSplineCurve r{c.degree, c.knots, Points(c.control.dim, count + 1)};
  r.knots.insert(r.knots.begin() + static_cast<std::ptrdiff_t>(s) + 1, t);
  // Q_i = P_i (i <= s-p), (1 - a_i) P_{i-1} + a_i P_i with a_i = (t - t_i)/(t_{i+p} - t_i)
  // (s-p < i <= s), P_{i-1} (i > s).
  for (std::size_t i = 0; i <= count; ++i) {
    double* q = r.control.coords.data() + i * dim;
    if (i + p <= s) {
      std::copy_n(c.control.coords.begin() + static_cast<std::ptrdiff_t>(i * dim), dim, q);
    } else if (i > s) {
      std::copy_n(c.control.coords.begin() + static_cast<std::ptrdiff_t>((i - 1) * dim), dim, q);
    } else {
      const double a = (t - c.knots[i]) / (c.knots[i + p] - c.knots[i]);
      for (std::size_t k = 0; k < dim; ++k)
        q[k] = (1 - a) * c.control.coords[(i - 1) * dim + k] + a * c.control.coords[i * dim + k];
    }
  }
  return r;
}

}  // namespace splinefig
