#pragma once
// Internal: the points of one span of a curve from its weight table, shared by the uniform
// (curve.cpp) and the non-uniform (nonuniform.cpp) samplers.
//
// A span's `order` control points P_i (D coordinates each) and a table E of `order` rows of
// K = grain * D weights, each weight repeated for the D coordinates of its parameter, give
//   out[k] = sum_i E[i*K + k] * P[i*D + k mod D],  k < K,
// summed in the order of i (so every path gives the same bits). Blocks of L outputs, L a
// multiple of D and of 4, use one register pattern per control point, so each output costs
// `order` multiply-adds and the stores are contiguous.
#include <cstddef>

namespace splinefig::detail {

template <std::size_t D>
constexpr std::size_t block_of() {
  return D == 3 ? 12 : (D == 1 || D == 2 || D == 4) ? 4 : 4 * D;
}

// Outputs k0 .. K-1 one at a time (the tail after the blocks).
inline void apply_weights_from(std::size_t k0, const double* E, std::size_t K, const double* P, std::size_t order,
                               std::size_t dim, double* o) {
  for (; k0 < K; ++k0) {
    double v = E[k0] * P[k0 % dim];
    for (std::size_t i = 1; i < order; ++i) v += E[i * K + k0] * P[i * dim + k0 % dim];
    o[k0] = v;
  }
}

// Cubic spans (order 4), the common case, with the four rows unrolled.
template <std::size_t D>
inline void apply_cubic_weights(const double* E, std::size_t K, const double* P, double* o) {
  constexpr std::size_t L = block_of<D>();
  const std::size_t Kb = K - K % L;
  const double *E0 = E, *E1 = E + K, *E2 = E + 2 * K, *E3 = E + 3 * K;
  double q0[L], q1[L], q2[L], q3[L];
  for (std::size_t m = 0; m < L; ++m) {
    q0[m] = P[m % D];
    q1[m] = P[D + m % D];
    q2[m] = P[2 * D + m % D];
    q3[m] = P[3 * D + m % D];
  }
  for (std::size_t k = 0; k < Kb; k += L)
    for (std::size_t m = 0; m < L; ++m)
      o[k + m] = E0[k + m] * q0[m] + E1[k + m] * q1[m] + E2[k + m] * q2[m] + E3[k + m] * q3[m];
  for (std::size_t k = Kb; k < K; ++k) {
    const std::size_t m = k % D;
    o[k] = E0[k] * q0[m] + E1[k] * q1[m] + E2[k] * q2[m] + E3[k] * q3[m];
  }
}

// Any order, D coordinates known at compile time.
template <std::size_t D>
inline void apply_weights(const double* E, std::size_t K, const double* P, std::size_t order, double* o) {
  if (order == 4) return apply_cubic_weights<D>(E, K, P, o);
  constexpr std::size_t L = 4 * D;
  std::size_t k0 = 0;
  for (; k0 + L <= K; k0 += L) {
    double acc[L];
    for (std::size_t m = 0; m < L; ++m) acc[m] = E[k0 + m] * P[m % D];
    for (std::size_t i = 1; i < order; ++i) {
      const double* e = E + i * K + k0;
      const double* pi = P + i * D;
      for (std::size_t m = 0; m < L; ++m) acc[m] += e[m] * pi[m % D];
    }
    for (std::size_t m = 0; m < L; ++m) o[k0 + m] = acc[m];
  }
  apply_weights_from(k0, E, K, P, order, D, o);
}

// Any order and dimension, the period spelled out in Q (scratch of order x 4*dim).
inline void apply_weights(const double* E, std::size_t K, const double* P, std::size_t order, std::size_t dim,
                          double* Q, double* o) {
  const std::size_t L = 4 * dim;
  for (std::size_t i = 0; i < order; ++i)
    for (std::size_t r = 0; r < 4; ++r)
      for (std::size_t q = 0; q < dim; ++q) Q[i * L + r * dim + q] = P[i * dim + q];
  std::size_t k0 = 0;
  for (; k0 + L <= K; k0 += L) {
    double* ob = o + k0;
    for (std::size_t m = 0; m < L; ++m) ob[m] = E[k0 + m] * Q[m];
    for (std::size_t i = 1; i < order; ++i) {
      const double* e = E + i * K + k0;
      const double* qi = Q + i * L;
      for (std::size_t m = 0; m < L; ++m) ob[m] += e[m] * qi[m];
    }
  }
  apply_weights_from(k0, E, K, P, order, dim, o);
}

// The K outputs of one span, for any dimension (1 to 4 with the fixed patterns).
inline void apply_span_weights(const double* E, std::size_t K, const double* P, std::size_t order, std::size_t dim,
                               double* Q, double* o) {
  switch (dim) {
    case 1: apply_weights<1>(E, K, P, order, o); break;
    case 2: apply_weights<2>(E, K, P, order, o); break;
    case 3: apply_weights<3>(E, K, P, order, o); break;
    case 4: apply_weights<4>(E, K, P, order, o); break;
    default: apply_weights(E, K, P, order, dim, Q, o);
  }
}

}  // namespace splinefig::detail
