// The kernel type: piecewise polynomials on unit intervals, and the non-polynomial comparison
// filters behind the same interface (kernel.hpp).
#include <splinefig/kernel/kernel.hpp>

#include "quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace splinefig {
namespace {

double sinc(double x) { return x == 0 ? 1.0 : std::sin(std::numbers::pi * x) / (std::numbers::pi * x); }

}  // namespace

double polynomial_value(const std::vector<double>& c, double u) {
  double v = 0;
  for (size_t m = c.size(); m-- > 0;) v = v * u + c[m];
  return v;
}

double polynomial_derivative(const std::vector<double>& c, int m, double u) {
  double v = 0;
  for (size_t p = c.size(); p-- > static_cast<size_t>(m);) {
    double coef = c[p];
    for (int k = 0; k < m; ++k) coef *= static_cast<double>(p - static_cast<size_t>(k));
    v = v * u + coef;
  }
  return v;
}

Kernel::Kernel() : name_("box"), support_{-0.5, 0.5}, pieces_{{1.0}} {}

long Kernel::piece_at(double s) const {
  // The piece with lo + p <= s < lo + p + 1, decided by exact comparisons (s - lo may round).
  const long last = static_cast<long>(pieces_.size()) - 1;
  long p = std::clamp(static_cast<long>(std::floor(s - support_.lo)), 0L, last);
  if (p > 0 && s < support_.lo + double(p)) --p;
  if (p < last && s >= support_.lo + double(p + 1)) ++p;
  return p;
}

Kernel Kernel::piecewise(std::string name, double lo, std::vector<std::vector<double>> pieces) {
  auto bad = [&](const std::string& why) { throw KernelError("kernel '" + name + "': " + why); };
  if (pieces.empty()) bad("no pieces");
  if (!std::isfinite(lo)) bad("lo is not finite");
  for (const auto& p : pieces) {
    if (p.empty()) bad("a piece without coefficients");
    for (double c : p)
      if (!std::isfinite(c)) bad("a coefficient is not finite");
  }
  Kernel k;
  k.name_ = std::move(name);
  k.support_ = {lo, lo + static_cast<double>(pieces.size())};
  k.pieces_ = std::move(pieces);
  k.continuity_ = -1;
  return k;
}

Kernel Kernel::box() { return Kernel(); }

Kernel Kernel::tent() { return piecewise("tent", -1, {{0.0, 1.0}, {1.0, -1.0}}); }

Kernel Kernel::lanczos(int a) {
  if (a < 1) throw KernelError("kernel 'lanczos" + std::to_string(a) + "': a must be at least 1");
  Kernel k;
  k.pieces_.clear();
  k.name_ = "lanczos" + std::to_string(a);
  k.support_ = {-double(a), double(a)};
  k.value_ = [a](double s) { return sinc(s) * sinc(s / a); };
  // sinc(s) sinc(s/a) vanishes at s = +-a with a vanishing first derivative (both factors'
  // zeros meet there: d/ds = sinc'(a) sinc(1) + sinc(a) sinc'(1)/a = 0), but its second
  // derivative 2 sinc'(a) sinc'(1) / a is not zero: C1.
  k.continuity_ = 1;
  return k;
}

double Kernel::operator()(double s) const {
  if (!(s >= support_.lo && s < support_.hi)) return 0.0;
  if (pieces_.empty()) return value_(s);
  const long p = piece_at(s);
  return polynomial_value(pieces_[static_cast<size_t>(p)], s - (support_.lo + double(p)));
}

double Kernel::integral() const {
  if (pieces_.empty()) {
    const double w = support_.hi - support_.lo;
    return detail::quadrature([&](double s) { return (*this)(s); }, support_.lo, support_.hi, detail::panels_for(w));
  }
  double sum = 0;
  for (const auto& p : pieces_)
    for (size_t m = 0; m < p.size(); ++m) sum += p[m] / double(m + 1);
  return sum;
}

int Kernel::degree() const {
  if (pieces_.empty()) return -1;
  int d = 0;
  for (const auto& p : pieces_) d = std::max(d, static_cast<int>(p.size()) - 1);
  return d;
}

double Kernel::derivative(double s, int m) const {
  if (pieces_.empty()) throw std::logic_error("kernel '" + name_ + "': derivative of a non-polynomial kernel");
  if (!(s >= support_.lo && s < support_.hi)) return 0.0;
  const long p = piece_at(s);
  return polynomial_derivative(pieces_[static_cast<size_t>(p)], m, s - (support_.lo + double(p)));
}

}  // namespace splinefig
