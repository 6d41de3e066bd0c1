#include "sweep.hpp"

namespace splinefig::render::detail {

// Adds to events_ every height in the common range of a and b where their order changes.
// Between consecutive vertex heights of either chain both are linear, so their gap is too:
// sampling the gap at those heights finds every sign change, and the root is interpolated.
void StripSweep::crossings(const Span& a, const Span& b) {
  const double lo = std::max(a.ta, b.ta), hi = std::min(a.tb, b.tb);
  if (!(hi > lo)) return;
  const auto& v = g_->verts;
  const std::size_t la = g_->chains[a.chain].last, lb = g_->chains[b.chain].last;
  std::size_t ka = a.k, kb = b.k;
  double y = lo;
  double d = x_on(a, ka, y) - x_on(b, kb, y);
  int last_sign = d > 0 ? 1 : (d < 0 ? -1 : 0);
  double y_prev = y, d_prev = d;
  while (y < hi) {
    // next sample: the lowest vertex height above y of either chain, or hi
    while (ka + 1 < la && v[ka + 1].y <= y) ++ka;
    while (kb + 1 < lb && v[kb + 1].y <= y) ++kb;
    double yn = hi;
    if (v[ka + 1].y > y) yn = std::min(yn, v[ka + 1].y);
    if (v[kb + 1].y > y) yn = std::min(yn, v[kb + 1].y);
    y = yn;
    double dn = x_at(ka, y) - x_at(kb, y);
    int s = dn > 0 ? 1 : (dn < 0 ? -1 : 0);
    // Every change of order is an event: a crossing (interpolated), and the two ends of a
    // stretch where the chains coincide (e.g. both projected onto the clip box's side).
    if (s != last_sign) {
      if (s != 0 && last_sign != 0) {
        double yc = y_prev + (y - y_prev) * (d_prev / (d_prev - dn));
        events_.push_back(std::clamp(yc, y_prev, y));
      } else {
        events_.push_back(s == 0 ? y : y_prev);
      }
    }
    last_sign = s;
    y_prev = y;
    d_prev = dn;
  }
}

}  // namespace splinefig::render::detail
