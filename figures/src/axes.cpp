// Data-to-pixel maps and 1-2-5 tick selection.
#include <splinefig/figures/axes.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace splinefig::figures {

double AxisMap::transfer(double v) const {
  switch (scale) {
    case Scale::Log:
      if (!(v > 0)) {
        if (name) throw std::domain_error(std::string("a log ") + name + " axis needs positive " + name + " data");
        throw std::domain_error("a log axis needs positive data");
      }
      return std::log10(v);
    case Scale::Decibel: return 20.0 * std::log10(std::max(std::abs(v), 1e-300));
    case Scale::Linear: break;
  }
  return v;
}

double AxisMap::lo() const { return scale == Scale::Log ? std::log10(d0) : d0; }
double AxisMap::hi() const { return scale == Scale::Log ? std::log10(d1) : d1; }

double AxisMap::to_pixel(double v) const { return p0 + (transfer(v) - lo()) / (hi() - lo()) * (p1 - p0); }

double AxisMap::from_pixel(double p) const {
  double t = lo() + (p - p0) / (p1 - p0) * (hi() - lo());
  switch (scale) {
    case Scale::Log: return std::pow(10.0, t);
    case Scale::Decibel: return std::pow(10.0, t / 20.0);
    case Scale::Linear: break;
  }
  return t;
}

std::string format_number(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", std::max(0, decimals), v);
  std::string s = buf;
  // "-0" and "-0.0" are zero.
  bool zero = s.find_first_not_of("-0.") == std::string::npos;
  if (zero) s.erase(0, s[0] == '-' ? 1 : 0);
  return s;
}

std::string tick_number(double v, int decimals) {
  std::string s = format_number(v, decimals);
  if (!s.empty() && s[0] == '-') s.replace(0, 1, "\u2212");
  return s;
}

std::string range_problem(double lo, double hi) {
  char buf[160];
  const double span = std::abs(hi - lo), size = std::max(std::abs(lo), std::abs(hi));
  if (!std::isfinite(lo) || !std::isfinite(hi)) {
    std::snprintf(buf, sizeof buf, "the range [%g, %g] is not finite", lo, hi);
  } else if (!std::isfinite(span)) {
    std::snprintf(buf, sizeof buf, "the range [%g, %g] is wider than the largest number", lo, hi);
  } else if (span < kMinAxisSpan || span < kMinRelativeAxisSpan * size) {
    std::snprintf(buf, sizeof buf, "the range [%.17g, %.17g] is too narrow (the span must be at least 1e-100 and 1e-12 of its ends)", lo, hi);
  } else {
    return {};
  }
  return buf;
}

double nice_step(double lo, double hi, double target) {
  double span = std::abs(hi - lo);
  target = std::max(target, 1.0);
  double raw = span / target;
  double p = std::pow(10.0, std::floor(std::log10(raw)));
  double best = p, best_err = 1e300;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    double step = m * p;
    double count = std::floor(span / step + 1e-9) + 1;
    double err = std::abs(count - (target + 1));
    if (err < best_err - 1e-12) best = step, best_err = err;
  }
  return best;
}

std::vector<Tick> nice_ticks(double lo, double hi, double target, double step) {
  if (lo > hi) std::swap(lo, hi);
  if (!(step > 0)) step = nice_step(lo, hi, target);
  if (!(step > 0 && std::isfinite(step) && std::isfinite(lo) && std::isfinite(hi))) return {};
  // Counted in double before anything becomes an integer.
  const double first = std::ceil(lo / step - 1e-9), last = std::floor(hi / step + 1e-9);
  if (!(last - first < kMaxTicks) || !(std::abs(first) < 0x1p53 && std::abs(last) < 0x1p53)) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "a tick step of %g gives more than %d ticks over [%g, %g]", step, kMaxTicks, lo, hi);
    throw TickError(buf);
  }
  int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  // 2.5-type steps never arise (1-2-5 only), but forced steps may need one more digit.
  double scaled = step * std::pow(10.0, decimals);
  if (std::abs(scaled - std::round(scaled)) > 1e-6) ++decimals;
  std::vector<Tick> ticks;
  const long long k0 = static_cast<long long>(first), k1 = static_cast<long long>(last);
  for (long long k = k0; k <= k1; ++k) {
    double v = k * step;
    if (std::abs(v) < step * 1e-9) v = 0;
    ticks.push_back({v, tick_number(v, decimals)});
  }
  return ticks;
}

std::vector<Tick> log_ticks(double lo, double hi) {
  if (lo > hi) std::swap(lo, hi);
  if (!(lo > 0 && hi < HUGE_VAL)) throw TickError("log ticks need a positive, finite range");
  int k0 = static_cast<int>(std::ceil(std::log10(lo) - 1e-9));
  int k1 = static_cast<int>(std::floor(std::log10(hi) + 1e-9));
  if (k1 - k0 < 1) return nice_ticks(lo, hi, 5);
  int every = std::max(1, (k1 - k0 + 7) / 8);
  std::vector<Tick> ticks;
  for (int k = k0; k <= k1; ++k) {
    if ((k - k0) % every) continue;
    // Every decade as a power, 10^0 and 10^1 too, so the labels read as one series.
    std::string label = "10^{" + (k < 0 ? "\u2212" + std::to_string(-k) : std::to_string(k)) + "}";
    ticks.push_back({std::pow(10.0, k), label});
  }
  return ticks;
}

}  // namespace splinefig::figures
