#pragma once
// Colours of the house style (docs/figures.md) and the palettes that colour families of curves.
#include <splinefig/renderer/renderer.hpp>

#include <string>
#include <string_view>

namespace splinefig::figures {

bool palette_known(std::string_view name);
// Colour i of n from a palette: "viridis" (perceptually ordered; sampled on [0, 0.58], where
// every colour has at least 3:1 contrast on white), "tab10" (matplotlib's categorical set as
// it is: four of its colours are under 3:1 on white), "grey" (sRGB 0.15 .. 0.55, also >= 3:1).
render::Color palette_color(std::string_view name, int i, int n);
// Viridis at t in [0, 1], interpolated in sRGB between published samples.
render::Color viridis(double t);

// The dash pattern of the i-th element that takes its colour from the axes palette (the default
// style cycle): solid, dashed [8, 4], dotted [2, 3], dash-dot [8, 3, 2, 3], long dashes
// [16, 4], dash-dot-dot [8, 3, 2, 3, 2, 3], then again, in pixels at 1x for butt caps. With
// the palette's colours, which are ordered in lightness, each series differs from the others
// of its panel in two ways, so none is told apart by hue alone (in greyscale, or by a
// colour-blind reader).
render::DashPattern cycle_dash(int i);
inline constexpr int kDashCycle = 6;

// "#rrggbb" of a linear-light colour (alpha dropped).
std::string to_hex(render::Color c);

}  // namespace splinefig::figures
