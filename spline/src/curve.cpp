// Curves through knots: end modes, evaluation at t, and the memo's sampling at `grain`.
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/segment.hpp>

#include "weight_table.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#if defined(__x86_64__) && defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace splinefig {

Ends parse_ends(std::string_view s) {
  if (s == "open") return Ends::open;
  if (s == "double" || s == "doubled") return Ends::doubled;
  if (s == "closed") return Ends::closed;
  throw SpecError("unknown end mode '" + std::string(s) + "' (known: open, double, closed)");
}

const char* to_string(Ends e) {
  switch (e) {
    case Ends::open: return "open";
    case Ends::doubled: return "double";
    case Ends::closed: return "closed";
  }
  return "?";
}

std::size_t min_knots(const Basis& b, Ends ends) {
  const std::size_t d = static_cast<std::size_t>(b.degree);
  switch (ends) {
    case Ends::open: return d + 1;
    case Ends::doubled: return std::max<std::size_t>(2, d - 1);
    case Ends::closed: return 3;
  }
  return d + 1;
}

Curve make_curve(const Basis& b, const Points& knots, Ends ends) {
  const std::size_t n = knots.size();
  const std::size_t need = min_knots(b, ends);
  if (n == 0 || knots.dim < 1)
    throw CurveError("no knots (" + b.spec + " with " + to_string(ends) + " ends needs at least " +
                     std::to_string(need) + ")");
  if (n < need)
    throw CurveError("too few knots: " + std::to_string(n) + " given, " + b.spec + " with " +
                     to_string(ends) + " ends needs at least " + std::to_string(need));
  Curve c{b, ends, n, Points(knots.dim)};
  Points& p = c.control;
  switch (ends) {
    case Ends::open:
      p = knots;
      break;
    case Ends::doubled:
      p.coords.reserve((n + 2) * static_cast<std::size_t>(knots.dim));
      p.push_back(knots[0]);
      p.coords.insert(p.coords.end(), knots.coords.begin(), knots.coords.end());
      p.push_back(knots[n - 1]);
      break;
    case Ends::closed: {
      // The memo's cyclic spline: for the cubic, last knot in front, first two behind.
      const std::size_t d = static_cast<std::size_t>(b.degree), h = (d - 1) / 2;
      p.coords.reserve((n + d) * static_cast<std::size_t>(knots.dim));
      for (std::size_t j = 0; j < n + d; ++j) p.push_back(knots[(j + n * (h + 1) - h) % n]);
      break;
    }
  }
  return c;
}

void piece_coefficients(const Curve& c, std::size_t i, std::span<double> a) {
  segment_coefficients(c.basis, c.piece_control(i), c.dim(), a);
}

PieceParameter locate(const Curve& c, double t) {
  const std::size_t s = c.segments();
  if (!(t > 0)) return {0, 0.0};  // also NaN
  if (t >= static_cast<double>(s)) return {s - 1, 1.0};
  const double f = std::floor(t);
  std::size_t i = static_cast<std::size_t>(f);
  if (i >= s) i = s - 1;
  return {i, t - static_cast<double>(i)};
}

void evaluate(const Curve& c, double t, int derivative, std::span<double> out) {
  const PieceParameter pp = locate(c, t);
  double a[64 * 8];
  std::vector<double> big;
  const std::size_t need = static_cast<std::size_t>(c.basis.order() * c.dim());
  std::span<double> coef(a, need);
  if (need > std::size(a)) {
    big.resize(need);
    coef = big;
  }
  piece_coefficients(c, pp.piece, coef);
  segment_point(coef, c.degree(), c.dim(), pp.u, derivative, out);
}

std::size_t sample_count(const Curve& c, int grain) {
  if (grain < 1) throw CurveError("grain must be at least 1, got " + std::to_string(grain));
  const std::size_t s = c.segments(), g = static_cast<std::size_t>(grain);
  const std::size_t limit = std::numeric_limits<std::size_t>::max() / 8 /
                            static_cast<std::size_t>(std::max(1, c.dim()));
  if (s > (limit - 1) / g) throw CurveError("too many points: " + std::to_string(s) + " pieces x grain " +
                                            std::to_string(grain));
  return s * g + 1;
}

namespace {

// Outputs of at least this many bytes are written with non-temporal (streaming) stores: far
// larger than a core's caches, they would be evicted before the caller reads them, and an
// ordinary store first reads its cache line from memory. With ordinary stores, a 10^6-knot 3-D
// curve at grain 16 (384 MB) took about the time of writing the same bytes plus that of the
// arithmetic, which does not overlap a full store buffer. Smaller outputs stay in cache for
// the caller, who reads them next. Streamed: cubic pieces of 1 to 4 coordinates whose outputs
// start on 16-byte boundaries (a 16-byte aligned output and grain x dim even); the values are
// the same, only where they are written from changes.
constexpr std::size_t stream_bytes = std::size_t{16} << 20;

#if defined(__x86_64__) && defined(__SSE2__)
constexpr bool can_stream = true;
// detail::apply_cubic_weights<D> with its stores streamed, four outputs at a time (two 16-byte
// stores): the same products summed in the same order (elementwise, no FMA contraction), so
// the same bits. o 16-byte aligned, K even.
template <std::size_t D>
inline void stream_cubic_weights(const double* E, std::size_t K, const double* P, double* o) {
  using v2 = double __attribute__((vector_size(16)));
  using v4 = double __attribute__((vector_size(32)));
  constexpr std::size_t L = detail::block_of<D>();
  static_assert(L % 4 == 0);
  const std::size_t Kb = K - K % L;
  const double *E0 = E, *E1 = E + K, *E2 = E + 2 * K, *E3 = E + 3 * K;
  double q[4][L];  // control point r's coordinates repeated with period D
  for (std::size_t r = 0; r < 4; ++r)
    for (std::size_t m = 0; m < L; ++m) q[r][m] = P[r * D + m % D];
  for (std::size_t k = 0; k < Kb; k += L)
    for (std::size_t h = 0; h < L / 4; ++h) {
      const std::size_t j = k + 4 * h;
      v4 e0, e1, e2, e3, q0, q1, q2, q3;
      std::memcpy(&e0, E0 + j, sizeof e0);
      std::memcpy(&e1, E1 + j, sizeof e1);
      std::memcpy(&e2, E2 + j, sizeof e2);
      std::memcpy(&e3, E3 + j, sizeof e3);
      std::memcpy(&q0, q[0] + 4 * h, sizeof q0);
      std::memcpy(&q1, q[1] + 4 * h, sizeof q1);
      std::memcpy(&q2, q[2] + 4 * h, sizeof q2);
      std::memcpy(&q3, q[3] + 4 * h, sizeof q3);
      const v4 v = e0 * q0 + e1 * q1 + e2 * q2 + e3 * q3;
      _mm_stream_pd(o + j, __m128d(v2{v[0], v[1]}));
      _mm_stream_pd(o + j + 2, __m128d(v2{v[2], v[3]}));
    }
  for (std::size_t k = Kb; k < K; ++k) {
    const std::size_t m = k % D;
    o[k] = E0[k] * P[m] + E1[k] * P[D + m] + E2[k] * P[2 * D + m] + E3[k] * P[3 * D + m];
  }
}
inline void stream_fence() { _mm_sfence(); }
#else
constexpr bool can_stream = false;
template <std::size_t D>
inline void stream_cubic_weights(const double* E, std::size_t K, const double* P, double* o) {
  detail::apply_cubic_weights<D>(E, K, P, o);
}
inline void stream_fence() {}
#endif

// Compiled twice where the compiler can (x86-64 GCC; clang refuses target_clones with flatten): for AVX2 and for the baseline,
// chosen at load time. No FMA contraction either way (ISO C++ mode), so both give the
// same bits, and so does the streamed path (the same sums, stored otherwise).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("avx2", "default"), flatten))
#endif
void sample_pieces(const double* ctrl, std::size_t pieces, int grain, int order, int dim, const double* E,
                   double* o) {
  // One piece after another (weight_table.hpp); piece i's control points start at point i.
  const std::size_t D = static_cast<std::size_t>(dim), n = static_cast<std::size_t>(order);
  const std::size_t K = static_cast<std::size_t>(grain) * D;
  const bool stream = can_stream && n == 4 && D <= 4 && K % 2 == 0 && reinterpret_cast<std::uintptr_t>(o) % 16 == 0 &&
                      pieces * K >= stream_bytes / sizeof(double);
  auto each = [&](auto fixed) {
    constexpr std::size_t F = decltype(fixed)::value;
    if (!stream) {
      for (std::size_t i = 0; i < pieces; ++i) detail::apply_weights<F>(E, K, ctrl + i * F, n, o + i * K);
      return;
    }
    for (std::size_t i = 0; i < pieces; ++i) stream_cubic_weights<F>(E, K, ctrl + i * F, o + i * K);
    stream_fence();
  };
  switch (D) {
    case 1: each(std::integral_constant<std::size_t, 1>{}); break;
    case 2: each(std::integral_constant<std::size_t, 2>{}); break;
    case 3: each(std::integral_constant<std::size_t, 3>{}); break;
    case 4: each(std::integral_constant<std::size_t, 4>{}); break;
    default: {
      std::vector<double> Q(n * 4 * D);
      for (std::size_t i = 0; i < pieces; ++i) detail::apply_weights(E, K, ctrl + i * D, n, D, Q.data(), o + i * K);
    }
  }
}

}  // namespace

void sample_into(const Curve& c, int grain, int derivative, std::span<double> out) {
  const std::size_t count = sample_count(c, grain);
  const int dim = c.dim(), order = c.basis.order();
  assert(out.size() == count * static_cast<std::size_t>(dim));
  (void)count;
  const std::size_t K = static_cast<std::size_t>(grain) * static_cast<std::size_t>(dim);
  // Weight table, expanded per coordinate: E[c*K + j*dim + d] = w_c(j/grain).
  std::vector<double> E(static_cast<std::size_t>(order) * K), w(static_cast<std::size_t>(order));
  for (int j = 0; j < grain; ++j) {
    basis_weights(c.basis, static_cast<double>(j) / grain, derivative, w);
    for (int col = 0; col < order; ++col)
      for (int d = 0; d < dim; ++d)
        E[static_cast<std::size_t>(col) * K + static_cast<std::size_t>(j * dim + d)] = w[static_cast<std::size_t>(col)];
  }
  const std::size_t pieces = c.segments();
  const double* ctrl = c.control.coords.data();
  double* o = out.data();
  sample_pieces(ctrl, pieces, grain, order, dim, E.data(), o);

  // The final point: u = 1 of the last piece; for a closed curve's position, the first point.
  double* last = o + pieces * K;
  if (c.ends == Ends::closed && derivative == 0) {
    std::copy(o, o + dim, last);
  } else {
    basis_weights(c.basis, 1.0, derivative, w);
    const double* p = ctrl + (pieces - 1) * static_cast<std::size_t>(dim);
    for (int d = 0; d < dim; ++d) {
      double v = w[0] * p[d];
      for (int col = 1; col < order; ++col) v += w[static_cast<std::size_t>(col)] * p[col * dim + d];
      last[d] = v;
    }
  }
}

Points sample(const Curve& c, int grain, int derivative) {
  Points out(c.dim(), sample_count(c, grain));
  sample_into(c, grain, derivative, out.coords);
  return out;
}

}  // namespace splinefig
