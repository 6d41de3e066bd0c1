// Filters from basis functions, and their analysis (see filter_analysis.hpp for the math).
#include <splinefig/spline/filter_analysis.hpp>

#include <algorithm>
#include <array>
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace splinefig {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Gauss-Legendre nodes and weights on [-1, 1] (16 points), by Newton's method on P_16.
struct GaussLegendre {
  static constexpr int n = 16;
  std::array<double, n> x{}, w{};
  GaussLegendre() {
    for (int i = 0; i < n; ++i) {
      double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 0;
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

// integral of g over [a, b] with `panels` equal panels of 16-point Gauss-Legendre.
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

double poly(const std::vector<double>& c, double u) {
  double v = 0;
  for (size_t m = c.size(); m-- > 0;) v = v * u + c[m];
  return v;
}

// m-th derivative of sum_p c[p] u^p at u.
double poly_derivative(const std::vector<double>& c, int m, double u) {
  double v = 0;
  for (size_t p = c.size(); p-- > static_cast<size_t>(m);) {
    double coef = c[p];
    for (int k = 0; k < m; ++k) coef *= static_cast<double>(p - static_cast<size_t>(k));
    v = v * u + coef;
  }
  return v;
}

int max_degree(const Filter& f) {
  int d = 0;
  for (const auto& p : f.pieces) d = std::max(d, static_cast<int>(p.c.size()) - 1);
  return d;
}

double sinc(double x) { return x == 0 ? 1.0 : std::sin(kPi * x) / (kPi * x); }

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

}  // namespace

Filter basis_filter(const Basis& b) {
  Filter f;
  f.spec = b.spec;
  f.basis = b;
  f.support = kernel_support(b);
  const int n = b.degree, h = (n - 1) / 2;
  // Column c of U M is the piece on [h-c, h-c+1); row r of M multiplies u^(n-r).
  for (int c = n; c >= 0; --c) {
    PolynomialPiece p{double(h - c), double(h - c + 1), {}};
    for (int m = 0; m <= n; ++m) p.c.push_back(b(n - m, c));
    f.pieces.push_back(std::move(p));
  }
  return f;
}

Filter parse_filter(std::string_view spec) {
  Filter f;
  if (spec == "box") {
    f.spec = "box";
    f.pieces = {{-0.5, 0.5, {1.0}}};
    f.support = {-0.5, 0.5};
    return f;
  }
  if (spec == "tent") {
    f.spec = "tent";
    f.pieces = {{-1, 0, {0.0, 1.0}}, {0, 1, {1.0, -1.0}}};
    f.support = {-1, 1};
    return f;
  }
  if (spec == "lanczos3") {
    f.spec = "lanczos3";
    f.lanczos = 3;
    f.support = {-3, 3};
    return f;
  }
  if (spec.substr(0, std::min<size_t>(spec.size(), spec.find(':'))).empty())
    throw SpecError("empty filter name");
  try {
    return basis_filter(parse_basis(spec));
  } catch (const SpecError& e) {
    const std::string what = e.what();
    if (what.rfind("unknown basis", 0) == 0)
      throw SpecError("unknown filter '" + std::string(spec.substr(0, spec.find(':'))) +
                      "' (known: box, tent, lanczos3 and the bases catmull-rom, cardinal, bspline, "
                      "tensioned-bspline, beta, uniform-bspline)");
    throw;
  }
}

double evaluate(const Filter& f, double s) {
  if (!(s >= f.support.lo && s < f.support.hi)) return 0.0;
  if (f.lanczos > 0) return sinc(s) * sinc(s / f.lanczos);
  auto it = std::upper_bound(f.pieces.begin(), f.pieces.end(), s,
                             [](double v, const PolynomialPiece& p) { return v < p.lo; });
  assert(it != f.pieces.begin());
  const PolynomialPiece& p = *(it - 1);
  if (s >= p.hi) return 0.0;  // a gap between pieces
  return poly(p.c, s - p.lo);
}

double integral(const Filter& f) {
  if (f.lanczos > 0) return quadrature([&](double s) { return evaluate(f, s); }, -f.lanczos, f.lanczos, 48);
  double sum = 0;
  for (const auto& p : f.pieces) {
    const double len = p.hi - p.lo;
    double lp = len;
    for (size_t m = 0; m < p.c.size(); ++m, lp *= len) sum += p.c[m] * lp / double(m + 1);
  }
  return sum;
}

double energy(const Filter& f) {
  if (f.lanczos > 0) {
    return quadrature([&](double s) { const double k = evaluate(f, s); return k * k; },
                      -f.lanczos, f.lanczos, 48);
  }
  double sum = 0;
  for (const auto& p : f.pieces) {
    const double len = p.hi - p.lo;
    for (size_t a = 0; a < p.c.size(); ++a)
      for (size_t b = 0; b < p.c.size(); ++b)
        sum += p.c[a] * p.c[b] * std::pow(len, double(a + b + 1)) / double(a + b + 1);
  }
  return sum;
}

int continuity(const Filter& f) {
  // sinc(s) sinc(s/a) vanishes at s = +-a with a vanishing first derivative (both factors'
  // zeros meet there: d/ds = sinc'(a) sinc(1) + sinc(a) sinc'(1)/a = 0), but its second
  // derivative 2 sinc'(a) sinc'(1) / a is not zero: C1.
  if (f.lanczos > 0) return 1;
  const int n = max_degree(f);
  int cls = n;
  static const std::vector<double> zero{0.0};
  for (size_t i = 0; i <= f.pieces.size(); ++i) {
    const PolynomialPiece* left = i > 0 ? &f.pieces[i - 1] : nullptr;
    const PolynomialPiece* right = i < f.pieces.size() ? &f.pieces[i] : nullptr;
    for (int m = 0; m <= n && m <= cls; ++m) {
      const double l = left ? poly_derivative(left->c, m, left->hi - left->lo) : 0.0;
      const double r = right ? poly_derivative(right->c, m, 0.0) : 0.0;
      if (std::abs(l - r) > 1e-9 * (1 + std::abs(l) + std::abs(r))) {
        cls = m - 1;
        break;
      }
    }
  }
  return cls;
}

bool interpolating(const Filter& f) {
  if (std::abs(evaluate(f, 0.0) - 1.0) > 1e-12) return false;
  for (double n = std::ceil(f.support.lo); n <= f.support.hi; n += 1)
    if (n != 0 && std::abs(evaluate(f, n)) > 1e-12) return false;
  return true;
}

std::complex<double> fourier(const Filter& f, double freq) {
  const double w = 2 * kPi * freq;
  if (f.lanczos > 0) {
    // Even kernel: K(f) = integral k(s) cos(w s) ds, an entire integrand.
    const int panels = 48 + 8 * static_cast<int>(std::ceil(std::abs(freq) * f.lanczos));
    return quadrature([&](double s) { return evaluate(f, s) * std::cos(w * s); }, -f.lanczos,
                      f.lanczos, panels);
  }
  std::complex<double> sum = 0;
  for (const auto& p : f.pieces) {
    const double len = p.hi - p.lo;
    const int n = static_cast<int>(p.c.size()) - 1;
    const auto I = moments(w * len, n);
    std::complex<double> piece = 0;
    double lp = len;
    for (int m = 0; m <= n; ++m, lp *= len) piece += p.c[static_cast<size_t>(m)] * lp * I[static_cast<size_t>(m)];
    sum += std::polar(1.0, -w * p.lo) * piece;
  }
  return sum;
}

double response(const Filter& f, double freq) { return std::abs(fourier(f, freq)); }

double step_value(const Filter& f, double t) {
  double num = 0, den = 0;
  for (double j = std::ceil(t - f.support.hi); j <= std::floor(t - f.support.lo); j += 1) {
    const double k = evaluate(f, t - j);
    den += k;
    if (j >= 0) num += k;
  }
  return num / den;
}

StepResponse step_response(const Filter& f) {
  // X(t) is 0 for t < lo and 1 for t > hi - 1: scan [lo - 1/2, hi + 1/2] finely, then refine the
  // extremes by golden-section search and the 0.1 / 0.9 crossings by bisection.
  const double a = f.support.lo - 0.5, b = f.support.hi + 0.5, h = 1.0 / 512;
  const int steps = static_cast<int>(std::ceil((b - a) / h));
  auto X = [&](double t) { return step_value(f, t); };
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

Basis mitchell_netravali_basis(double b, double c) {
  Basis m{"mitchell-netravali", "mitchell-netravali:b=" + fmt(b) + ",c=" + fmt(c), 3, {}};
  m.m = {(-b - 6 * c) / 6, (12 - 9 * b - 6 * c) / 6, (-12 + 9 * b + 6 * c) / 6, (b + 6 * c) / 6,
         (3 * b + 12 * c) / 6, (-18 + 12 * b + 6 * c) / 6, (18 - 15 * b - 12 * c) / 6, -c,
         (-3 * b - 6 * c) / 6, 0, (3 * b + 6 * c) / 6, 0,
         b / 6, (6 - 2 * b) / 6, b / 6, 0};
  return m;
}

std::optional<MitchellNetravali> mitchell_netravali(const Filter& f, std::string* why) {
  auto no = [&](std::string reason) {
    if (why) *why = std::move(reason);
    return std::nullopt;
  };
  if (!f.basis) return no("not a cubic spline basis function");
  const Basis& m = *f.basis;
  if (m.degree != 3) return no("degree " + std::to_string(m.degree) + ", not a cubic");
  const MitchellNetravali bc{6 * m(3, 0), -m(1, 3)};
  const Basis ref = mitchell_netravali_basis(bc.b, bc.c);
  for (size_t i = 0; i < 16; ++i)
    if (std::abs(ref.m[i] - m.m[i]) > 1e-12 * (1 + std::abs(m.m[i]))) {
      for (double s : {0.25, 0.5, 0.75, 1.25, 1.5, 1.75})
        if (std::abs(evaluate(f, s) - evaluate(f, -s)) > 1e-12) return no("asymmetric kernel");
      if (continuity(f) < 1) return no("not C1");
      return no("not a partition of unity");
    }
  return bc;
}

FilterReport analyse(const Filter& f) {
  FilterReport r;
  r.spec = f.spec;
  r.support = f.support;
  r.integral = integral(f);
  r.energy = energy(f);
  r.continuity = continuity(f);
  r.interpolating = interpolating(f);
  r.response_at_0 = response(f, 0);
  r.response_at_quarter = response(f, 0.25);
  r.response_at_nyquist = response(f, 0.5);
  r.droop = 1 - r.response_at_quarter / r.response_at_0;
  // Parseval: integral over all f of |K|^2 equals integral of k^2; |K| is even for real k.
  const double pass = 2 * quadrature([&](double fr) { return std::norm(fourier(f, fr)); }, 0.0, 0.5, 8);
  r.leakage = 1 - pass / r.energy;
  r.step = step_response(f);
  r.bc = mitchell_netravali(f, &r.not_bc);
  return r;
}

std::string report_text(const FilterReport& r) {
  std::string s;
  auto line = [&](const std::string& k, const std::string& v) { s += k + ": " + v + "\n"; };
  line("filter", r.spec);
  line("support", "[" + fmt(r.support.lo) + ", " + fmt(r.support.hi) + "]");
  line("integral", fmt(r.integral));
  line("energy", fmt(r.energy));
  line("continuity", r.continuity < 0 ? "discontinuous" : "C" + std::to_string(r.continuity));
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
