// The "1 4 1" systems of seed 003 solved by tridiagonal elimination, and the Bezier pieces.
#include <splinefig/spline/interp.hpp>
#include <splinefig/spline/curve.hpp>

#include <algorithm>
#include <cassert>
#include <stdexcept>
#include <string>
#include <vector>

namespace splinefig {
namespace {

// Solves the tridiagonal system with unit sub- and super-diagonals and the diagonal
// (first, middle, ..., middle, last), for every coordinate of the rows rhs[0..n) (overwritten
// with the solution). Thomas elimination; stable because every row is strictly diagonally
// dominant (4 > 1 + 1; an end row 2 > 1 or 8 > 1): each pivot stays >= 1.5.
//
// The eliminated super-diagonal c'_i = 1/(middle - c'_{i-1}) is a contraction that reaches its
// fixed point (2 - sqrt(3) for the 1-4-1 rows) bit for bit after a few dozen rows; from then
// on the stored value is reused, so the work is O(n) with O(1) extra memory and the result is
// identical to storing every c'_i.
void solve_unit_tridiagonal(double first, double middle, double last, std::size_t n, std::size_t dim, double* rhs) {
  assert(n >= 1);
  if (n == 1) {
    for (std::size_t c = 0; c < dim; ++c) rhs[c] /= first;
    return;
  }
  std::vector<double> cp;  // c'_0 .. c'_k; c'_i = c'_k for i > k once it has stopped changing
  cp.reserve(64);
  cp.push_back(1 / first);
  bool fixed = false;
  for (std::size_t c = 0; c < dim; ++c) rhs[c] *= cp[0];
  for (std::size_t i = 1; i < n; ++i) {
    const double prev = fixed ? cp.back() : cp[i - 1];
    const double inv = 1 / ((i + 1 == n ? last : middle) - prev);
    if (!fixed && i + 1 < n) {
      fixed = inv == prev;
      if (!fixed) cp.push_back(inv);
    }
    double* di = rhs + i * dim;
    const double* dp = di - dim;
    for (std::size_t c = 0; c < dim; ++c) di[c] = (di[c] - dp[c]) * inv;
  }
  for (std::size_t i = n - 1; i-- > 0;) {
    const double ci = i < cp.size() ? cp[i] : cp.back();
    double* di = rhs + i * dim;
    const double* dn = di + dim;
    for (std::size_t c = 0; c < dim; ++c) di[c] -= ci * dn[c];
  }
}

[[noreturn]] void too_few_points(const Points& data, std::size_t minimum, const char* what) {
  throw CurveError(std::string(what) + " interpolation needs at least " + std::to_string(minimum) +
                              " data points, got " + std::to_string(data.size()));
}

// The check stays inline, apart from the message, so that the optimizer sees the bound in the
// callers: interpolate_periodic's z.coords.back() is then known to index a vector of n >= 3,
// where GCC 12 (-O3) otherwise warns of an index -1 (-Warray-bounds) for an empty one.
inline void require_points(const Points& data, std::size_t minimum, const char* what) {
  if (data.dim < 1 || data.size() < minimum) too_few_points(data, minimum, what);
}

}  // namespace

Interpolant interpolate_relaxed(const Points& data) {
  require_points(data, 2, "relaxed");
  const std::size_t n = data.size() - 1, dim = static_cast<std::size_t>(data.dim);
  Interpolant s{EndCondition::relaxed, data, data};
  if (n == 1) return s;  // B = S: a straight segment
  // Unknowns B_1..B_{n-1}, solved in place: rows 6S_i, with S_0 and S_n moved to the right in
  // the end rows.
  double* b = s.control.coords.data();
  for (std::size_t k = dim; k < n * dim; ++k) b[k] *= 6;
  for (std::size_t c = 0; c < dim; ++c) {
    b[dim + c] -= data.coords[c];
    b[(n - 1) * dim + c] -= data.coords[n * dim + c];
  }
  solve_unit_tridiagonal(4, 4, 4, n - 1, dim, b + dim);
  return s;
}

Interpolant interpolate_clamped(const Points& data, std::span<const double> v, std::span<const double> w) {
  require_points(data, 2, "clamped");
  const std::size_t n = data.size() - 1, dim = static_cast<std::size_t>(data.dim);
  if (v.size() != dim || w.size() != dim)
    throw CurveError("clamped interpolation: end velocities need " + std::to_string(dim) +
                                " coordinates (the data's dimension)");
  // Unknowns B_0..B_n: 2B_0 + B_1 = 3S_0 + v, B_{i-1} + 4B_i + B_{i+1} = 6S_i, B_{n-1} + 2B_n = 3S_n - w.
  Points rhs(data.dim, n + 1);
  for (std::size_t i = 0; i <= n; ++i)
    for (std::size_t c = 0; c < dim; ++c) rhs.coords[i * dim + c] = 6 * data.coords[i * dim + c];
  for (std::size_t c = 0; c < dim; ++c) {
    rhs.coords[c] = 3 * data.coords[c] + v[c];
    rhs.coords[n * dim + c] = 3 * data.coords[n * dim + c] - w[c];
  }
  solve_unit_tridiagonal(2, 4, 2, n + 1, dim, rhs.coords.data());
  return Interpolant{EndCondition::clamped, data, std::move(rhs)};
}

Interpolant interpolate_periodic(const Points& data) {
  require_points(data, 3, "periodic");
  const std::size_t n = data.size() - 1, dim = static_cast<std::size_t>(data.dim);
  for (std::size_t c = 0; c < dim; ++c)
    if (data.coords[c] != data.coords[n * dim + c])
      throw CurveError("periodic interpolation: the last data point must repeat the first");
  // Unknowns B_0..B_{n-1} on a cycle: B_{i-1} + 4B_i + B_{i+1} = 6S_i, indices mod n.
  Points x(data.dim, n);
  if (n == 2) {
    // [4 2; 2 4] B = 6 S (the two neighbours of each unknown are the same point).
    for (std::size_t c = 0; c < dim; ++c) {
      const double s0 = data.coords[c], s1 = data.coords[dim + c];
      x.coords[c] = (4 * s0 - 2 * s1) / 2;
      x.coords[dim + c] = (4 * s1 - 2 * s0) / 2;
    }
  } else {
    // Sherman-Morrison: A = T + u v^T with u = (g, 0, ..., 0, 1), v = (1, 0, ..., 0, 1/g),
    // g = -4, so T is tridiagonal with diagonal (4 - g, 4, ..., 4, 4 - 1/g) and still
    // diagonally dominant. x = y - (v.y / (1 + v.z)) z with T y = 6S, T z = u.
    const double g = -4;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < dim; ++c) x.coords[i * dim + c] = 6 * data.coords[i * dim + c];
    solve_unit_tridiagonal(4 - g, 4, 4 - 1 / g, n, dim, x.coords.data());
    Points z(1, n);
    z.coords.front() = g;
    z.coords.back() = 1;
    solve_unit_tridiagonal(4 - g, 4, 4 - 1 / g, n, 1, z.coords.data());
    const double vz = z.coords.front() + z.coords.back() / g;
    for (std::size_t c = 0; c < dim; ++c) {
      const double vy = x.coords[c] + x.coords[(n - 1) * dim + c] / g;
      const double f = vy / (1 + vz);
      for (std::size_t i = 0; i < n; ++i) x.coords[i * dim + c] -= f * z.coords[i];
    }
  }
  x.coords.resize((n + 1) * dim);
  std::copy_n(x.coords.begin(), dim, x.coords.begin() + static_cast<std::ptrdiff_t>(n * dim));
  return Interpolant{EndCondition::periodic, data, std::move(x)};
}

Points relaxed_joints(const Points& control) {
  if (control.size() < 2) throw CurveError("a relaxed B-spline needs at least 2 control points");
  const std::size_t n = control.size() - 1, dim = static_cast<std::size_t>(control.dim);
  Points s = control;
  for (std::size_t i = 1; i < n; ++i)
    for (std::size_t c = 0; c < dim; ++c) {
      const double* b = control.coords.data() + i * dim + c;
      s.coords[i * dim + c] = (b[-static_cast<std::ptrdiff_t>(dim)] + 4 * b[0] + b[dim]) / 6;
    }
  return s;
}

namespace {

BezierSpline pieces_from(const Points& joints, const Points& control) {
  const std::size_t n = joints.size() - 1, dim = static_cast<std::size_t>(joints.dim);
  BezierSpline b{Points(joints.dim, 3 * n + 1)};
  double* out = b.points.coords.data();
  for (std::size_t i = 0; i <= n; ++i)
    for (std::size_t c = 0; c < dim; ++c) out[3 * i * dim + c] = joints.coords[i * dim + c];
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < dim; ++c) {
      const double b0 = control.coords[i * dim + c], b1 = control.coords[(i + 1) * dim + c];
      out[(3 * i + 1) * dim + c] = (2 * b0 + b1) / 3;
      out[(3 * i + 2) * dim + c] = (b0 + 2 * b1) / 3;
    }
  return b;
}

}  // namespace

BezierSpline bezier_pieces(const Interpolant& s) { return pieces_from(s.data, s.control); }

BezierSpline relaxed_bspline_bezier(const Points& control) {
  return pieces_from(relaxed_joints(control), control);
}

void evaluate(const Interpolant& s, double t, int derivative, std::span<double> out) {
  // Piece i+1 directly from S_i, S_{i+1}, B_i, B_{i+1}, without building all pieces.
  const std::size_t n = s.pieces(), dim = static_cast<std::size_t>(s.data.dim);
  assert(n >= 1 && out.size() == dim);
  std::size_t i = t <= 0 ? 0 : std::min(static_cast<std::size_t>(t), n - 1);
  BezierSpline one{Points(s.data.dim, 4)};
  for (std::size_t c = 0; c < dim; ++c) {
    const double b0 = s.control.coords[i * dim + c], b1 = s.control.coords[(i + 1) * dim + c];
    one.points.coords[c] = s.data.coords[i * dim + c];
    one.points.coords[dim + c] = (2 * b0 + b1) / 3;
    one.points.coords[2 * dim + c] = (b0 + 2 * b1) / 3;
    one.points.coords[3 * dim + c] = s.data.coords[(i + 1) * dim + c];
  }
  splinefig::evaluate(one, t - static_cast<double>(i), derivative, out);
}

Points sample(const Interpolant& s, int grain) {
  if (grain < 1) throw CurveError("grain must be at least 1, got " + std::to_string(grain));
  const std::size_t n = s.pieces(), dim = static_cast<std::size_t>(s.data.dim);
  const std::size_t g = static_cast<std::size_t>(grain);
  Points out(s.data.dim, n * g + 1);
  // Bernstein weights for u = j/grain, shared by every piece.
  std::vector<double> w(4 * g);
  for (std::size_t j = 0; j < g; ++j) {
    const double u = static_cast<double>(j) / static_cast<double>(g), v = 1 - u;
    w[4 * j] = v * v * v, w[4 * j + 1] = 3 * u * v * v, w[4 * j + 2] = 3 * u * u * v, w[4 * j + 3] = u * u * u;
  }
  double* o = out.coords.data();
  for (std::size_t i = 0; i < n; ++i) {
    const double* s0 = s.data.coords.data() + i * dim;
    const double* b0 = s.control.coords.data() + i * dim;
    for (std::size_t j = 0; j < g; ++j, o += dim) {
      const double* wj = &w[4 * j];
      for (std::size_t c = 0; c < dim; ++c) {
        const double p1 = (2 * b0[c] + b0[dim + c]) / 3, p2 = (b0[c] + 2 * b0[dim + c]) / 3;
        o[c] = wj[0] * s0[c] + wj[1] * p1 + wj[2] * p2 + wj[3] * s0[dim + c];
      }
    }
  }
  std::copy_n(s.data.coords.begin() + static_cast<std::ptrdiff_t>(n * dim), dim, o);
  return out;
}

Interpolant relaxed_basis(int n) {
  if (n < 1) throw CurveError("relaxed basis functions need n >= 1, got " + std::to_string(n));
  const std::size_t m = static_cast<std::size_t>(n) + 1;
  Points unit(n + 1, m);
  for (std::size_t k = 0; k < m; ++k) unit.coords[k * m + k] = 1;
  return interpolate_relaxed(unit);
}

}  // namespace splinefig
