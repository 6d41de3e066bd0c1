#pragma once
// The heights an item's geometry can reach, found from its recorded arguments before any
// geometry is built: the rasterizer's threads use it to give an item that lies within one
// block of rows to that block alone (rasterize.cpp).
#include <splinefig/renderer/renderer.hpp>

namespace splinefig::render::detail {

// [y0, y1] holds every point of the item's exact geometry (outline, fill, glyphs, image
// rectangle), in canvas pixels before any filter shift, with a margin of at least one pixel for
// rounding. False when no such bound is known (a non-finite coordinate).
bool item_y_range(const DrawItem& item, double& y0, double& y1);

}  // namespace splinefig::render::detail
