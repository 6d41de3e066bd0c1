// Filter analysis of a kernel (see analysis.hpp for the math).
#include <splinefig/kernel/analysis.hpp>

#include "quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace splinefig {
namespace {

using detail::quadrature;

// I_m(t) = integral_0^1 u^m e^{-itu} du for m = 0..n. From integrating by parts,
// I_m = (m I_{m-1} - e^{-it}) / (it). Upwards each step multiplies an error by m/|t|, so it is
// used for |t| >= max(n, 2); below that the same relation runs downwards,
// I_{m-1} = (it I_m + e^{-it}) / m, which damps errors by |t|/m, from a start 60 orders above.
std::vector<std::complex<double>> moments(double t, int n) {
  std::vector<std::complex<double>> out(static_cast<size_t>(n + 1));
  const std::complex<double> e = std::polar(1.0, -t), it(0, t);
  if (std::abs(t) >= std::max(n, 2)) {
    out[0] = (1.0 - e) / it;
    for (int m = 1; m <= n; ++m) out[static_cast<size_t>(m)] = (double(m) * out[static_cast<size_t>(m - 1)] - e) / it;
    return out;
  }
  std::complex<double> cur = 0;
  for (int m = n + 60; m >= 1; --m) {
    cur = (it * cur + e) / double(m);  // now I_{m-1}
    if (m - 1 <= n) out[static_cast<size_t>(m - 1)] = cur;
  }
  return out;
}

std::string fmt(double v) {
  if (v == 0) v = 0;  // no "-0"
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// The m-th derivative just left and just right of knot i (lo + i), for i = 0 .. pieces.
double left_derivative(const Kernel& k, size_t i, int m) {
  return i > 0 ? polynomial_derivative(k.pieces()[i - 1], m, 1.0) : 0.0;
}
double right_derivative(const Kernel& k, size_t i, int m) {
  return i < k.pieces().size() ? polynomial_derivative(k.pieces()[i], m, 0.0) : 0.0;
}

}  // namespace

double energy(const Kernel& k) {
  if (!k.polynomial()) {
    const Support s = k.support();
    return quadrature([&](double x) { const double v = k(x); return v * v; }, s.lo, s.hi,
                      detail::panels_for(s.hi - s.lo));
  }
  double sum = 0;
  for (const auto& p : k.pieces())
    for (size_t a = 0; a < p.size(); ++a)
      for (size_t b = 0; b < p.size(); ++b) sum += p[a] * p[b] / double(a + b + 1);
  return sum;
}

std::vector<double> jumps(const Kernel& k, int m) {
  std::vector<double> out;
  for (size_t i = 0; i <= k.pieces().size(); ++i) out.push_back(right_derivative(k, i, m) - left_derivative(k, i, m));
  return out;
}

int continuity(const Kernel& k) {
  if (!k.polynomial()) return k.declared_continuity();
  const int n = k.degree();
  for (int m = 0; m <= n; ++m) {
    double scale = 0;
    for (size_t i = 0; i <= k.pieces().size(); ++i)
      scale = std::max({scale, std::abs(left_derivative(k, i, m)), std::abs(right_derivative(k, i, m))});
    for (double j : jumps(k, m))
      if (std::abs(j) > kContinuityTolerance * scale) return m - 1;
  }
  return n;
}

bool interpolating(const Kernel& k) {
  if (std::abs(k(0.0) - 1.0) > 1e-12) return false;
  const Support s = k.support();
  for (double n = std::ceil(s.lo); n <= s.hi; n += 1)
    if (n != 0 && std::abs(k(n)) > 1e-12) return false;
  return true;
}

std::complex<double> fourier(const Kernel& k, double freq) {
  const double w = 2 * std::numbers::pi * freq;
  const Support s = k.support();
  if (!k.polynomial()) {
    // An even kernel: K(f) = integral k(s) cos(w s) ds, an entire integrand.
    const double width = s.hi - s.lo;
    const int panels = detail::panels_for(width) + 8 * static_cast<int>(std::ceil(std::abs(freq) * width / 2));
    return quadrature([&](double x) { return k(x) * std::cos(w * x); }, s.lo, s.hi, panels);
  }
  std::complex<double> sum = 0;
  for (size_t p = 0; p < k.pieces().size(); ++p) {
    const auto& c = k.pieces()[p];
    const int n = static_cast<int>(c.size()) - 1;
    const auto I = moments(w, n);
    std::complex<double> piece = 0;
    for (int m = 0; m <= n; ++m) piece += c[static_cast<size_t>(m)] * I[static_cast<size_t>(m)];
    sum += std::polar(1.0, -w * (s.lo + double(p))) * piece;
  }
  return sum;
}

double response(const Kernel& k, double freq) { return std::abs(fourier(k, freq)); }

double step_value(const Kernel& k, double t) {
  const Support s = k.support();
  double num = 0, den = 0;
  for (double j = std::ceil(t - s.hi); j <= std::floor(t - s.lo); j += 1) {
    const double v = k(t - j);
    den += v;
    if (j >= 0) num += v;
  }
  return num / den;
}

StepResponse step_response(const Kernel& k) {
  // X(t) is 0 for t < lo and 1 for t > hi - 1: scan [lo - 1/2, hi + 1/2] finely, then refine the
  // extremes by golden-section search and the 0.1 / 0.9 crossings by bisection.
  const double a = k.support().lo - 0.5, b = k.support().hi + 0.5, h = 1.0 / 512;
  const int steps = static_cast<int>(std::ceil((b - a) / h));
  auto X = [&](double t) { return step_value(k, t); };
  int imax = 0, imin = 0;
  double vmax = -1e300, vmin = 1e300;
  std::vector<double> v(static_cast<size_t>(steps + 1));
  for (int i = 0; i <= steps; ++i) {
    v[static_cast<size_t>(i)] = X(a + i * h);
    if (v[static_cast<size_t>(i)] > vmax) vmax = v[static_cast<size_t>(i)], imax = i;
    if (v[static_cast<size_t>(i)] < vmin) vmin = v[static_cast<size_t>(i)], imin = i;
  }
  auto golden = [&](int i, double sign) {
    double lo = a + (i - 1) * h, hi = a + (i + 1) * h, best = sign * X(a + i * h);
    const double g = 0.6180339887498949;
    for (int it = 0; it < 60; ++it) {
      const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
      const double f1 = sign * X(m1), f2 = sign * X(m2);
      best = std::max({best, f1, f2});
      if (f1 > f2) hi = m2; else lo = m1;
    }
    return sign * best;
  };
  StepResponse r;
  r.overshoot = std::max(0.0, golden(imax, 1) - 1);
  r.undershoot = std::max(0.0, -golden(imin, -1));
  int i90 = 0;
  while (i90 < steps && v[static_cast<size_t>(i90)] < 0.9) ++i90;
  int i10 = i90;
  while (i10 > 0 && v[static_cast<size_t>(i10)] > 0.1) --i10;
  auto cross = [&](double lo, double hi, double level) {  // X(lo) < level <= X(hi)
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (X(mid) < level ? lo : hi) = mid;
    }
    return hi;
  };
  const double t90 = i90 > 0 ? cross(a + (i90 - 1) * h, a + i90 * h, 0.9) : a;
  const double t10 = cross(a + i10 * h, a + (i10 + 1) * h, 0.1);
  r.rise = std::max(0.0, t90 - t10);
  return r;
}

std::optional<MitchellNetravali> mitchell_netravali(const Kernel& k, std::string* why) {
  auto no = [&](std::string reason) {
    if (why) *why = std::move(reason);
    return std::nullopt;
  };
  if (!k.polynomial()) return no("not a piecewise polynomial");
  if (k.degree() != 3) return no("degree " + std::to_string(k.degree()) + ", not a cubic");
  if (k.support().lo != -2 || k.pieces().size() != 4) return no("support not [-2, 2]");
  const auto& p = k.pieces();
  auto close = [](double a, double b) { return std::abs(a - b) <= 1e-12 * (1 + std::abs(a) + std::abs(b)); };
  // Symmetric: piece q at u equals piece 3 - q at 1 - u, checked at 4 points (cubics).
  for (size_t q = 0; q < 4; ++q)
    for (double u : {0.0, 0.25, 0.5, 0.75})
      if (!close(polynomial_value(p[q], u), polynomial_value(p[3 - q], 1 - u))) return no("asymmetric kernel");
  if (continuity(k) < 1) return no("not C1");
  // Partition of unity: sum_j k(t - j) = sum_q piece_q(t) for t in [0, 1), as a polynomial.
  for (size_t m = 0; m < 4; ++m) {
    double sum = 0;
    for (const auto& c : p) sum += m < c.size() ? c[m] : 0.0;
    if (!close(sum, m == 0 ? 1.0 : 0.0)) return no("not a partition of unity");
  }
  const double c2 = p[0].size() > 2 ? p[0][2] : 0.0;
  return MitchellNetravali{6 * p[3][0], -c2};
}

FilterReport analyse(const Kernel& k) {
  FilterReport r;
  r.name = k.name();
  r.support = k.support();
  r.integral = k.integral();
  r.energy = energy(k);
  r.continuity = continuity(k);
  r.interpolating = interpolating(k);
  r.response_at_0 = response(k, 0);
  r.response_at_quarter = response(k, 0.25);
  r.response_at_nyquist = response(k, 0.5);
  r.droop = 1 - r.response_at_quarter / r.response_at_0;
  // Parseval: integral over all f of |K|^2 equals integral of k^2; |K| is even for real k.
  const double pass = 2 * quadrature([&](double fr) { return std::norm(fourier(k, fr)); }, 0.0, 0.5, 8);
  r.leakage = 1 - pass / r.energy;
  r.step = step_response(k);
  r.bc = mitchell_netravali(k, &r.not_bc);
  return r;
}

std::string report_text(const FilterReport& r) {
  std::string s;
  auto line = [&](const std::string& key, const std::string& v) { s += key + ": " + v + "\n"; };
  line("filter", r.name);
  // '[' and 'C', not "[" and "C": GCC 12 warns of a bogus overlap (-Wrestrict, GCC PR 105329)
  // for a one-character string literal + a temporary std::string.
  line("support", '[' + fmt(r.support.lo) + ", " + fmt(r.support.hi) + "]");
  line("integral", fmt(r.integral));
  line("energy", fmt(r.energy));
  line("continuity", r.continuity < 0 ? "discontinuous" : 'C' + std::to_string(r.continuity));
  line("interpolating", r.interpolating ? "yes" : "no");
  line("response_at_0", fmt(r.response_at_0));
  line("response_at_0.25", fmt(r.response_at_quarter));
  line("response_at_nyquist", fmt(r.response_at_nyquist));
  line("passband_droop_at_0.25", fmt(r.droop) + " (" + fmt(20 * std::log10(1 - r.droop)) + " dB)");
  line("stopband_leakage", fmt(r.leakage) + " (energy fraction above f = 0.5)");
  line("step_overshoot", fmt(r.step.overshoot));
  line("step_undershoot", fmt(r.step.undershoot));
  line("step_rise_10_90", fmt(r.step.rise));
  if (r.bc)
    line("mitchell_netravali", "B=" + fmt(r.bc->b) + " C=" + fmt(r.bc->c) +
                                   " (B+2C=" + fmt(r.bc->b + 2 * r.bc->c) + ")");
  else
    line("mitchell_netravali", "none (" + r.not_bc + ")");
  return s;
}

}  // namespace splinefig
