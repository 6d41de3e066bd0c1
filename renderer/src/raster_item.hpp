#pragma once
// Drawing a raster image item (Scene::image): sampling at canvas pixel centres, then over.
#include "compositor.hpp"

#include <splinefig/renderer/renderer.hpp>

namespace splinefig::render::detail {

// Composites the raster into rows [r0, r1) of `img`. A pixel's result depends only on the
// raster and the pixel, so bands give identical bytes for any thread count.
void composite_raster(const ImageItem& r, const Compositor& comp, Image& img, int r0, int r1);

}  // namespace splinefig::render::detail
