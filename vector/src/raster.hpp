#pragma once
// What both writers share: the scene's items, sRGB colours and raster items as Cairo image
// surfaces.
#include <splinefig/renderer/path.hpp>
#include <splinefig/renderer/renderer.hpp>

#include <cairo.h>

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace splinefig::vector::detail {

// The scene's items in drawing order; throws render::DrawError if an item is clipped (SVG and
// PDF as written here carry no clip paths).
std::span<const render::DrawItem> unclipped_items(const render::Scene& scene);

struct Srgb {
  double r, g, b, a;  // sRGB-encoded colour, straight alpha
};
Srgb to_srgb(render::Color c);
// "#rrggbb" of the colour's sRGB encoding, 8 bits (the PNG's rounding).
std::string hex(render::Color c);

// An ARGB32 surface (premultiplied sRGB, 8 bits) of a linear, associated-alpha RGBA image.
// The caller destroys it.
cairo_surface_t* image_surface(const Image& im);
// The image as PNG bytes (sRGB, straight alpha).
std::vector<unsigned char> png_bytes(const Image& im);

}  // namespace splinefig::vector::detail
