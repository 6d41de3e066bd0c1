// Palettes. Viridis: the 11 samples at t = 0, 0.1, ..., 1 of matplotlib's colormap
// (van der Walt and Smith, 2015), interpolated linearly in sRGB. The families drawn from it
// and from grey stop where lines still have a contrast of 3:1 on the white background (WCAG's
// level for graphics): viridis at t = 0.58 (3.15:1; t = 0.6 is just under 3:1, the yellow-green
// end about 1.3:1), grey at sRGB 0.55 (3.35:1).
#include <splinefig/figures/palette.hpp>
#include <splinefig/image/srgb.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace splinefig::figures {
namespace {

constexpr std::array<unsigned, 11> kViridis = {0x440154, 0x482475, 0x414487, 0x355f8d, 0x2a788e, 0x21918c,
                                               0x22a884, 0x44bf70, 0x7ad151, 0xbddf26, 0xfde725};
constexpr std::array<unsigned, 10> kTab10 = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd,
                                             0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf};

constexpr double kViridisDarkEnough = 0.58;

render::Color from_srgb(double r, double g, double b) {
  return {splinefig::srgb_to_linear(static_cast<float>(r)), splinefig::srgb_to_linear(static_cast<float>(g)),
          splinefig::srgb_to_linear(static_cast<float>(b)), 1};
}

double channel(unsigned rgb, int shift) { return ((rgb >> shift) & 0xff) / 255.0; }

}  // namespace

bool palette_known(std::string_view name) { return name == "viridis" || name == "tab10" || name == "grey"; }

render::Color viridis(double t) {
  t = std::clamp(t, 0.0, 1.0) * 10.0;
  int i = std::min(9, static_cast<int>(std::floor(t)));
  double f = t - i;
  auto mix = [&](int shift) { return (1 - f) * channel(kViridis[i], shift) + f * channel(kViridis[i + 1], shift); };
  return from_srgb(mix(16), mix(8), mix(0));
}

render::Color palette_color(std::string_view name, int i, int n) {
  if (name == "tab10") {
    unsigned c = kTab10[static_cast<size_t>(i) % kTab10.size()];
    return from_srgb(channel(c, 16), channel(c, 8), channel(c, 0));
  }
  double t = n <= 1 ? 0.0 : static_cast<double>(i) / (n - 1);
  if (name == "grey") {
    double v = 0.15 + 0.40 * t;
    return from_srgb(v, v, v);
  }
  return viridis(kViridisDarkEnough * t);
}

render::DashPattern cycle_dash(int i) {
  switch (((i % kDashCycle) + kDashCycle) % kDashCycle) {
    case 1: return {8, 4};
    case 2: return {2, 3};
    case 3: return {8, 3, 2, 3};
    case 4: return {16, 4};
    case 5: return {8, 3, 2, 3, 2, 3};
    default: return {};
  }
}

std::string to_hex(render::Color c) {
  auto q = [](float v) { return static_cast<int>(std::lround(std::clamp(splinefig::linear_to_srgb(v), 0.0f, 1.0f) * 255.0f)); };
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", q(c.r), q(c.g), q(c.b));
  return buf;
}

}  // namespace splinefig::figures
