#pragma once
// The clip path a Scene records its items under (Scene::set_clip). Geometry is built at
// rasterization time, when the region that can affect the canvas (canvas plus filter support)
// is known.
#include <splinefig/renderer/path.hpp>
#include <splinefig/renderer/renderer.hpp>

namespace splinefig::render {

// A clip path: what the items recorded after Scene::set_clip are intersected with, exactly.
struct ClipRegion {
  Path path;
  FillRule rule = FillRule::NonZero;
};

}  // namespace splinefig::render
