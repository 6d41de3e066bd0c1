// Arc length: the memo's polygon method and adaptive Gauss-Kronrod with a safeguarded
// Newton inverse (see arclength.hpp).
#include <splinefig/spline/arclength.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/segment.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace splinefig {
namespace {

// Gauss-Kronrod 7/15 on [-1, 1] (Kronrod 1965; the values QUADPACK tabulates). Nodes
// xk[1], xk[3], xk[5], xk[7] are the 7-point Gauss nodes with weights wg.
constexpr double xk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                          0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                          0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                          0.207784955007898467600689403773245, 0.0};
constexpr double wk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                          0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                          0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                          0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                          0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

// The speed |X'(u)| of one piece, from its derivative's Horner coefficients.
struct Speed {
  int deg1 = 0, dim = 0;       // degree of X', dimension
  std::vector<double> d1, d2;  // coefficients of X' and X'' (row r multiplies u^(deg-r))

  Speed(const Curve& c, std::size_t piece) : deg1(c.degree() - 1), dim(c.dim()) {
    const int n = c.degree();
    std::vector<double> a(static_cast<size_t>(c.basis.order() * dim));
    piece_coefficients(c, piece, a);
    d1.assign(static_cast<size_t>(n * dim), 0.0);
    d2.assign(static_cast<size_t>(std::max(1, n - 1) * dim), 0.0);
    for (int r = 0; r < n; ++r)
      for (int d = 0; d < dim; ++d) d1[static_cast<size_t>(r * dim + d)] = (n - r) * a[static_cast<size_t>(r * dim + d)];
    for (int r = 0; r < n - 1; ++r)
      for (int d = 0; d < dim; ++d)
        d2[static_cast<size_t>(r * dim + d)] = (n - 1 - r) * d1[static_cast<size_t>(r * dim + d)];
  }

  double component(const std::vector<double>& coef, int deg, int d, double u) const {
    double v = 0;
    for (int r = 0; r <= deg; ++r) v = v * u + coef[static_cast<size_t>(r * dim + d)];
    return v;
  }
  double operator()(double u) const {
    double s2 = 0;
    for (int d = 0; d < dim; ++d) {
      const double v = component(d1, deg1, d, u);
      s2 += v * v;
    }
    return std::sqrt(s2);
  }
  // X'.X'', half the derivative of the squared speed.
  double speed_slope(double u) const {
    if (deg1 < 1) return 0;
    double p = 0;
    for (int d = 0; d < dim; ++d) p += component(d1, deg1, d, u) * component(d2, deg1 - 1, d, u);
    return p;
  }
};

constexpr std::size_t kMaxIntervals = std::size_t(1) << 20;

struct Estimate {
  double value, error;
};

Estimate gauss_kronrod(const Speed& f, double a, double b) {
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  double k = wk[7] * f(c), g = wg[3] * f(c);
  for (int i = 0; i < 7; ++i) {
    const double y = f(c - h * xk[i]) + f(c + h * xk[i]);
    k += wk[i] * y;
    if (i % 2 == 1) g += wg[i / 2] * y;
  }
  return {k * h, std::abs((k - g) * h)};
}

// Appends the accepted subintervals of [a, b] (piece-local u) in order to the table.
void integrate(const Speed& f, double offset, double a, double b, Estimate e, double tol_per_unit,
               int depth, ArcLength& out) {
  // Also accepted: an estimate that is not finite (a speed beyond the range of a double; the
  // caller reports it) and any interval once the table is this large, so that the work stays
  // bounded for any curve.
  if (e.error <= tol_per_unit * (b - a) || depth >= 60 || b - a <= 1e-15 || !std::isfinite(e.error) ||
      out.t.size() >= kMaxIntervals) {
    out.t.push_back(b >= 1.0 ? offset + 1.0 : offset + b);
    out.s.push_back(out.s.back() + e.value);
    return;
  }
  const double m = 0.5 * (a + b);
  integrate(f, offset, a, m, gauss_kronrod(f, a, m), tol_per_unit, depth + 1, out);
  integrate(f, offset, m, b, gauss_kronrod(f, m, b), tol_per_unit, depth + 1, out);
}

// Local minima of the speed inside (0,1): X'.X'' changes sign from - to +. A cubic's X'.X''
// is of degree 3, so 64 samples separate its roots unless two nearly coincide (then the
// speed has no sharp minimum there to split at).
std::vector<double> speed_minima(const Speed& f) {
  std::vector<double> roots;
  constexpr int samples = 64;
  double u0 = 0, p0 = f.speed_slope(0);
  for (int j = 1; j <= samples; ++j) {
    const double u1 = static_cast<double>(j) / samples, p1 = f.speed_slope(u1);
    if (p0 < 0 && p1 >= 0) {
      double lo = u0, hi = u1;
      for (int it = 0; it < 100 && hi - lo > 1e-17; ++it) {
        const double m = 0.5 * (lo + hi);
        (f.speed_slope(m) < 0 ? lo : hi) = m;
      }
      if (hi > 0 && hi < 1) roots.push_back(hi);
    }
    u0 = u1;
    p0 = p1;
  }
  return roots;
}

}  // namespace

ArcLength arc_length(const Curve& c, double tolerance) {
  const std::size_t pieces = c.segments();
  std::vector<Speed> speeds;
  speeds.reserve(pieces);
  double rough = 0;
  for (std::size_t i = 0; i < pieces; ++i) {
    speeds.emplace_back(c, i);
    rough += gauss_kronrod(speeds.back(), 0, 1).value;
  }
  ArcLength out;
  out.t.push_back(0);
  out.s.push_back(0);
  // An absolute tolerance per unit of t that sums to `tolerance` of the whole length.
  const double tol = tolerance * rough / static_cast<double>(pieces);
  for (std::size_t i = 0; i < pieces; ++i) {
    const Speed& f = speeds[i];
    std::vector<double> cuts = speed_minima(f);
    cuts.insert(cuts.begin(), 0.0);
    cuts.push_back(1.0);
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
      integrate(f, static_cast<double>(i), cuts[k], cuts[k + 1], gauss_kronrod(f, cuts[k], cuts[k + 1]), tol, 0,
                out);
  }
  if (!std::isfinite(out.total()))
    throw std::overflow_error("arc length: the curve's length is beyond the range of a double");
  return out;
}

namespace {

// The interval [a.t[k], a.t[k+1]] and its piece.
std::size_t piece_of(const ArcLength& a, std::size_t k) {
  return static_cast<std::size_t>(std::floor(0.5 * (a.t[k] + a.t[k + 1])));
}

}  // namespace

double length_at(const Curve& c, const ArcLength& a, double t) {
  if (!(t > 0)) return 0;
  if (t >= a.t.back()) return a.total();
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(a.t.begin(), a.t.end(), t) - a.t.begin()) - 1;
  const std::size_t i = piece_of(a, k);
  const Speed f(c, i);
  const double off = static_cast<double>(i);
  return a.s[k] + gauss_kronrod(f, a.t[k] - off, t - off).value;
}

double parameter_at_length(const Curve& c, const ArcLength& a, double s) {
  if (!(s > 0)) return 0;
  if (s >= a.total()) return a.t.back();
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(a.s.begin(), a.s.end(), s) - a.s.begin()) - 1;
  if (k + 1 >= a.t.size()) return a.t.back();
  const std::size_t i = piece_of(a, k);
  const Speed f(c, i);
  const double off = static_cast<double>(i);
  // Solve F(u) = s[k] + integral_{u_k}^{u} |X'| - s = 0 on the bracket [lo, hi] (piece-local u).
  double lo = a.t[k] - off, hi = a.t[k + 1] - off;
  const double ds = a.s[k + 1] - a.s[k];
  double u = ds > 0 ? lo + (hi - lo) * (s - a.s[k]) / ds : lo;
  const double ftol = 4 * std::numeric_limits<double>::epsilon() * a.total();
  for (int it = 0; it < 200; ++it) {
    const double F = a.s[k] + gauss_kronrod(f, a.t[k] - off, u).value - s;
    if (std::abs(F) <= ftol) break;
    (F < 0 ? lo : hi) = u;
    if (hi - lo <= 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, off + hi)) break;
    const double v = f(u);
    const double next = v > 0 ? u - F / v : lo - 1;
    u = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
  }
  return off + u;
}

std::vector<double> evenly_spaced_parameters(const Curve& c, std::size_t count) {
  if (count < 2) throw CurveError("evenly spaced points: count must be at least 2");
  const ArcLength a = arc_length(c);
  const double L = a.total(), T = static_cast<double>(c.segments());
  std::vector<double> t(count);
  const double n = static_cast<double>(count - 1);
  for (std::size_t k = 0; k < count; ++k) {
    const double f = static_cast<double>(k) / n;
    t[k] = L > 0 ? parameter_at_length(c, a, f * L) : f * T;
  }
  t.front() = 0;
  t.back() = T;
  return t;
}

double polygon_length(const Curve& c, int grain) {
  const Points p = sample(c, grain);
  double L = 0;
  for (std::size_t j = 1; j < p.size(); ++j) {
    double d2 = 0;
    for (int d = 0; d < p.dim; ++d) {
      const double e = p[j][d] - p[j - 1][d];
      d2 += e * e;
    }
    L += std::sqrt(d2);
  }
  return L;
}

std::vector<double> polygon_evenly_spaced_parameters(const Curve& c, int grain, std::size_t count) {
  if (count < 2) throw CurveError("evenly spaced points: count must be at least 2");
  const Points p = sample(c, grain);
  std::vector<double> cum(p.size(), 0.0);
  for (std::size_t j = 1; j < p.size(); ++j) {
    double d2 = 0;
    for (int d = 0; d < p.dim; ++d) {
      const double e = p[j][d] - p[j - 1][d];
      d2 += e * e;
    }
    cum[j] = cum[j - 1] + std::sqrt(d2);
  }
  const double L = cum.back(), T = static_cast<double>(c.segments());
  std::vector<double> t(count);
  for (std::size_t k = 0; k < count; ++k) {
    const double f = static_cast<double>(k) / static_cast<double>(count - 1);
    if (!(L > 0)) {
      t[k] = f * T;
      continue;
    }
    const double target = f * L;
    std::size_t j = static_cast<std::size_t>(std::upper_bound(cum.begin(), cum.end(), target) - cum.begin());
    j = std::clamp<std::size_t>(j, 1, cum.size() - 1);
    const double chord = cum[j] - cum[j - 1];
    const double frac = chord > 0 ? (target - cum[j - 1]) / chord : 0.0;
    t[k] = (static_cast<double>(j - 1) + std::clamp(frac, 0.0, 1.0)) / grain;
  }
  t.front() = 0;
  t.back() = T;
  return t;
}

Points evaluate_at(const Curve& c, const std::vector<double>& t, int derivative) {
  Points out(c.dim(), t.size());
  const double T = static_cast<double>(c.segments());
  for (std::size_t k = 0; k < t.size(); ++k) {
    const bool wrap = c.ends == Ends::closed && derivative == 0 && t[k] >= T;
    evaluate(c, wrap ? 0.0 : t[k], derivative, out[k]);
  }
  return out;
}

}  // namespace splinefig
