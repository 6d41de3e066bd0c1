#pragma once
// Colours of the house style (docs/figures.md) and the palettes that colour families of curves.
#include <splinefig/renderer/renderer.hpp>

#include <string>
#include <string_view>

namespace splinefig::figures {

bool palette_known(std::string_view name);
// Colour i of n from a palette: "viridis" (perceptually ordered; sampled on [0, 0.9] so the
// last colour is not the pale yellow end), "tab10" (categorical), "grey".
render::Color palette_color(std::string_view name, int i, int n);
// Viridis at t in [0, 1], interpolated in sRGB between published samples.
render::Color viridis(double t);

// "#rrggbb" of a linear-light colour (alpha dropped).
std::string to_hex(render::Color c);

}  // namespace splinefig::figures
