#pragma once
// Axes: the map from data to pixels, and tick selection.
//
// An axis maps its range [d0, d1] linearly onto pixels [p0, p1] after a transfer f:
// f(v) = v (linear), log10 v (log), or 20 log10 |v| (db: the range is given in dB and the
// data are magnitudes). For y, p0 is the bottom of the plot box and p1 its top (docs/conventions.md).
#include <splinefig/figures/spec.hpp>

#include <string>
#include <vector>

namespace splinefig::figures {

// Ticks that cannot be made for a range: more than kMaxTicks of them, or log ticks over a range
// that is not positive and finite. The layout names the axis key it comes from (x_tick_step,
// x_range).
struct TickError : ErrorOf<std::invalid_argument, ErrorKind::bad_input> {
  using ErrorOf::ErrorOf;
};

struct AxisMap {
  Scale scale = Scale::Linear;
  double d0 = 0, d1 = 1;  // the range as given (dB for db axes)
  double p0 = 0, p1 = 1;  // pixels
  char name = 0;          // 'x' or 'y', for messages

  // data -> the linear domain of the axis; throws std::domain_error for v <= 0 on a log axis
  // (an element with such data is an error, never silently left out).
  double transfer(double v) const;
  double to_pixel(double v) const;
  double from_pixel(double p) const;  // inverse, in the linear domain's terms mapped back to data
  double lo() const;  // the range in the linear domain
  double hi() const;
};

struct Tick {
  double value;       // data value (magnitude for db axes mapped in dB: value is in dB)
  std::string label;
};

// Why [lo, hi] cannot be an axis range (empty if it can): both ends and the span must be
// finite, the span at least kMinAxisSpan and at least kMinRelativeAxisSpan of the larger end's
// magnitude, so that the pixel map and the ticks have distinct numbers to work with.
std::string range_problem(double lo, double hi);
// A forced tick step that gives more than kMaxTicks (base/limits.hpp) is an error.

// Nice ticks for [lo, hi] (either order): steps 1, 2 or 5 times a power of ten, about
// `target` of them, every tick inside the range (to 1e-9 of the step). `step` > 0 forces
// the step. Labels print just the digits the step needs. Throws TickError when the
// step would give more than kMaxTicks ticks; no ticks for a range without extent.
std::vector<Tick> nice_ticks(double lo, double hi, double target, double step = 0);
// The step nice_ticks would use.
double nice_step(double lo, double hi, double target);
// Decades 10^k inside [lo, hi] (lo, hi > 0), labelled "10^{k}" (label markup; 10^0 and 10^1
// as powers too, a negative k with the minus sign U+2212); falls back to nice_ticks when the
// range spans less than one decade. Throws TickError unless 0 < lo, hi < inf.
std::vector<Tick> log_ticks(double lo, double hi);
// A number with `decimals` digits after the point ("-0" printed as "0").
std::string format_number(double v, int decimals);
// The same as a tick label: negative numbers with the minus sign U+2212, not a hyphen.
std::string tick_number(double v, int decimals);

}  // namespace splinefig::figures
