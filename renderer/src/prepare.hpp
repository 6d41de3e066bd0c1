#pragma once
// From a Scene's items to what the rasterizer consumes: each item's exact geometry as
// y-monotone chains (clipped to the region that can affect the canvas).
#include "compositor.hpp"
#include "clip_region.hpp"
#include "outline_stream.hpp"
#include "sweep.hpp"

#include <cstdint>

namespace splinefig::render::detail {

struct Prepared {
  Shape shape;
  const ImageItem* raster = nullptr;  // images only
  Paint paint;         // the item's colour, premultiplied in the canvas's blend space
  int row0 = 0, row1 = 0;  // canvas rows the item can touch, [row0, row1)
  // The rasterizer's counter of this item's sweep work on several threads; kNoWorkSlot for items
  // that are not swept (images, simple shapes, nothing on the canvas).
  static constexpr std::uint32_t kNoWorkSlot = ~std::uint32_t{0};
  std::uint32_t work_slot = kNoWorkSlot;
};

// `clip_path`: the item's clip (Scene::set_clip), or null. `clip` is the region whose geometry matters (the canvas grown by the filter's support), in
// the coordinates the rasterizer works in (already shifted to the filter's cell grid).
// `shift` is subtracted from every input point. A long stroke's outline is built in pieces on
// up to `threads` threads (stroke.hpp: OutlinePieces); the result does not depend on `threads`.
void prepare_item(const DrawItem& item, const ClipRegion* clip_path, const Compositor& comp, Vec2 shift, const Box& clip,
                  Geometry& g, Prepared& out, int canvas_h, int threads = 1);

// For one thread drawing under the box filter: an item that is a long stroke (one whose outline
// is built in pieces) is started with its outline left to `stream` (outline_stream.hpp), which
// builds it as the item's bands come: its paint, an empty shape and the rows the outline can
// reach, which may be more than prepare_item's (rows without ink are drawn as nothing). False,
// with nothing done, for every other item. `clip` is the canvas.
bool prepare_streamed(const DrawItem& item, const Compositor& comp, const Box& clip, Geometry& g, Prepared& out,
                      int canvas_h, OutlineStream& stream);

}  // namespace splinefig::render::detail
