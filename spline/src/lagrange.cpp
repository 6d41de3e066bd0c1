// Barycentric Lagrange interpolation.
#include <splinefig/spline/lagrange.hpp>
#include <splinefig/spline/curve.hpp>

#include <algorithm>
#include <cassert>
#include <stdexcept>
#include <string>

namespace splinefig {

LagrangePolynomial lagrange(std::vector<double> t, Points data) {
  if (t.empty() || t.size() != data.size())
    throw CurveError("Lagrange interpolation needs one parameter value per data point (" +
                                std::to_string(t.size()) + " for " + std::to_string(data.size()) + ")");
  const std::size_t n = t.size();
  std::vector<double> w(n, 1.0);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j < n; ++j) {
      if (j == k) continue;
      const double d = t[k] - t[j];
      if (d == 0)
        throw CurveError("Lagrange interpolation: parameter values " + std::to_string(j) + " and " +
                                    std::to_string(k) + " coincide");
      w[k] /= d;
    }
  return LagrangePolynomial{std::move(t), std::move(data), std::move(w)};
}

void evaluate(const LagrangePolynomial& p, double t, std::span<double> out) {
  const std::size_t n = p.t.size(), dim = static_cast<std::size_t>(p.data.dim);
  assert(out.size() == dim);
  for (std::size_t k = 0; k < n; ++k)
    if (t == p.t[k]) {
      std::copy_n(p.data.coords.begin() + static_cast<std::ptrdiff_t>(k * dim), dim, out.begin());
      return;
    }
  std::fill(out.begin(), out.end(), 0.0);
  double denom = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double c = p.weights[k] / (t - p.t[k]);
    denom += c;
    for (std::size_t q = 0; q < dim; ++q) out[q] += c * p.data.coords[k * dim + q];
  }
  for (std::size_t q = 0; q < dim; ++q) out[q] /= denom;
}

}  // namespace splinefig
