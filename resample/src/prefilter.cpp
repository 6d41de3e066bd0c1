// The exact inverse prefilter (derivation in prefilter.hpp).
#include <splinefig/resample/prefilter.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "splinefig/base/parallel.hpp"

namespace splinefig {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// The system p_i = a c_{i-1} + b c_i + g c_{i+1} on one line of n values, ready to solve.
struct Solver {
  double a = 0, b = 1, g = 0;
  Edge edge = Edge::clamp;
  long n = 0;
  // Tridiagonal edges: Gaussian elimination without pivoting, l[i] the multiplier of row i and
  // d[i] its pivot; d tends to -g z2 and l to -z1, the steady recursions.
  std::vector<double> l, d;
  // wrap: causal pole z1, anticausal pole zeta, gain.
  double z1 = 0, zeta = 0, gain = 1;
};

// Roots of g z^2 + b z + a with |z1| <= |z2|; a vanishing g puts z2 at infinity.
void roots(double a, double b, double g, std::complex<double>& z1, std::complex<double>& z2) {
  if (g == 0) {
    z1 = b != 0 ? -a / b : INFINITY;
    z2 = INFINITY;
    return;
  }
  const double disc = b * b - 4 * a * g;
  if (disc < 0) {
    z1 = std::complex<double>(-b, std::sqrt(-disc)) / (2 * g);
    z2 = std::conj(z1);
    return;
  }
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  z1 = q / g;
  z2 = q != 0 ? std::complex<double>(a / q) : std::complex<double>(0);
  if (std::abs(z1) > std::abs(z2)) std::swap(z1, z2);
}

Solver make_solver(const SampledKernel& h, Edge edge, long n) {
  Solver s;
  s.a = h.right;
  s.b = h.centre;
  s.g = h.left;
  s.edge = edge;
  s.n = n;
  if (edge == Edge::wrap) {
    std::complex<double> r1, r2;
    roots(s.a, s.b, s.g, r1, r2);
    s.z1 = r1.real();
    if (s.g == 0) {
      s.zeta = 0;
      s.gain = s.b;
    } else {
      s.zeta = 1 / r2.real();
      s.gain = -s.g * r2.real();
    }
    return s;
  }
  // clamp and mirror read c_{-1} = c_0 and c_n = c_{n-1}; black reads zeros.
  const bool fold = edge != Edge::black;
  s.l.resize(static_cast<size_t>(n));
  s.d.resize(static_cast<size_t>(n));
  for (long i = 0; i < n; ++i) {
    double diag = s.b;
    if (fold && i == 0) diag += s.a;
    if (fold && i == n - 1) diag += s.g;
    const double li = i == 0 ? 0 : s.a / s.d[static_cast<size_t>(i - 1)];
    s.l[static_cast<size_t>(i)] = li;
    s.d[static_cast<size_t>(i)] = diag - (i == 0 ? 0 : li * s.g);
    if (std::abs(s.d[static_cast<size_t>(i)]) < 1e-12)
      throw ResampleError("interpolating prefilter: the system for " + std::to_string(n) +
                                  " samples is singular");
  }
  return s;
}

// Solves the system on n vectors of L floats, vector i at base + i*stride, in place. Arithmetic
// in double, storage in float.
void solve(const Solver& s, float* base, long stride, long L, std::vector<double>& tmp) {
  const long n = s.n;
  auto at = [&](long i) { return base + i * stride; };
  if (s.edge == Edge::wrap) {
    if (n == 1) {
      for (long k = 0; k < L; ++k) at(0)[k] = static_cast<float>(at(0)[k] / (s.a + s.b + s.g));
      return;
    }
    // Causal y_i = x_i + z1 y_{i-1}, periodic: y_0 = sum_{k<n} z1^k x_{-k mod n} / (1 - z1^n).
    auto periodic_start = [&](double z, long from, long dir) {
      tmp.assign(static_cast<size_t>(L), 0.0);
      double zk = 1;
      for (long k = 0; k < n && std::abs(zk) > 1e-20; ++k, zk *= z) {
        const float* v = at(((from + dir * k) % n + n) % n);
        for (long j = 0; j < L; ++j) tmp[static_cast<size_t>(j)] += zk * v[j];
      }
      const double norm = 1 - std::pow(z, static_cast<double>(n));
      for (long j = 0; j < L; ++j) tmp[static_cast<size_t>(j)] /= norm;
    };
    periodic_start(s.z1, 0, -1);
    for (long j = 0; j < L; ++j) at(0)[j] = static_cast<float>(tmp[static_cast<size_t>(j)]);
    for (long i = 1; i < n; ++i)
      for (long j = 0; j < L; ++j) at(i)[j] = static_cast<float>(at(i)[j] + s.z1 * double(at(i - 1)[j]));
    // Anticausal c_i = y_i + zeta c_{i+1}, periodic, then the gain.
    periodic_start(s.zeta, n - 1, 1);
    for (long j = 0; j < L; ++j) at(n - 1)[j] = static_cast<float>(tmp[static_cast<size_t>(j)]);
    for (long i = n - 2; i >= 0; --i)
      for (long j = 0; j < L; ++j) at(i)[j] = static_cast<float>(at(i)[j] + s.zeta * double(at(i + 1)[j]));
    for (long i = 0; i < n; ++i)
      for (long j = 0; j < L; ++j) at(i)[j] = static_cast<float>(at(i)[j] / s.gain);
    return;
  }
  for (long i = 1; i < n; ++i) {
    const double li = s.l[static_cast<size_t>(i)];
    for (long j = 0; j < L; ++j) at(i)[j] = static_cast<float>(at(i)[j] - li * double(at(i - 1)[j]));
  }
  for (long j = 0; j < L; ++j) at(n - 1)[j] = static_cast<float>(at(n - 1)[j] / s.d[static_cast<size_t>(n - 1)]);
  for (long i = n - 2; i >= 0; --i) {
    const double di = s.d[static_cast<size_t>(i)];
    for (long j = 0; j < L; ++j)
      at(i)[j] = static_cast<float>((at(i)[j] - s.g * double(at(i + 1)[j])) / di);
  }
}

// Runs work(c, scratch) for each c in [0, count), each thread with a scratch vector of its own.
template <class F>
void for_each_line(long count, int threads, F&& work) {
  std::vector<std::vector<double>> scratch(static_cast<std::size_t>(worker_count(threads)));
  parallel_for(static_cast<std::size_t>(count), threads, [&](std::size_t c, int worker) {
    work(static_cast<long>(c), scratch[static_cast<std::size_t>(worker)]);
  });
}

}  // namespace

SampledKernel sampled_kernel(const Kernel& k) {
  for (double j = std::ceil(k.support().lo); j <= k.support().hi; j += 1)
    if (std::abs(j) >= 2 && std::abs(k(j)) > 1e-12)
      throw ResampleError("interpolating prefilter: filter " + k.name() + " is not zero at " +
                                  num(j) + "; only kernels sampled as k(-1), k(0), k(1) are supported");
  const double km = k(-1), k0 = k(0), kp = k(1);
  const double sum = km + k0 + kp;
  if (!(std::abs(sum) > 1e-12)) throw ResampleError("interpolating prefilter: filter " + k.name() + " sums to zero at the integers");
  SampledKernel h{km / sum, k0 / sum, kp / sum};
  std::complex<double> z1, z2;
  roots(h.right, h.centre, h.left, z1, z2);
  const double m1 = std::abs(z1), m2 = std::abs(z2);
  if (!(m1 < 1 - 1e-9 && m2 > 1 + 1e-9))
    throw ResampleError("interpolating prefilter: filter " + k.name() + " has no stable inverse: its samples (k(-1), k(0), k(1)) = (" +
                                num(km) + ", " + num(k0) + ", " + num(kp) + ") give roots of modulus " +
                                num(m1) + " and " + num(m2) + ", not one inside and one outside the unit circle");
  return h;
}

void prefilter_line(float* p, long n, long stride, const SampledKernel& h, Edge edge) {
  std::vector<double> tmp;
  solve(make_solver(h, edge, n), p, stride, 1, tmp);
}

void prefilter(Image& img, const Kernel& k, Edge edge, int threads) {
  const SampledKernel h = sampled_kernel(k);
  if (h.left == 0 && h.right == 0) return;  // an interpolating kernel: the identity
  const long C = img.channels, W = img.width, H = img.height;
  // Rows: the C channels of a pixel are the lanes of one vector, the pixels the line.
  const Solver rows = make_solver(h, edge, W);
  for_each_line(H, threads, [&](long y, std::vector<double>& tmp) {
    solve(rows, img.row(static_cast<int>(y)), C, C, tmp);
  });
  // Columns: a block of consecutive floats of every row is one vector, the rows the line.
  const Solver cols = make_solver(h, edge, H);
  const long stride = W * C, block = 256, blocks = (stride + block - 1) / block;
  for_each_line(blocks, threads, [&](long b, std::vector<double>& tmp) {
    solve(cols, img.pixels.data() + b * block, stride, std::min(block, stride - b * block), tmp);
  });
}

}  // namespace splinefig
