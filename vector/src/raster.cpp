#include "raster.hpp"

#include <splinefig/image/srgb.hpp>
#include <splinefig/vector/vector.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace splinefig::vector::detail {

std::span<const render::DrawItem> unclipped_items(const render::Scene& scene) {
  if (scene.clipped())
    throw render::DrawError("the scene has clipped items, which only the rasterizer draws (SVG and PDF do not carry clip paths)");
  return scene.items();
}

Srgb to_srgb(render::Color c) {
  auto e = [](float v) { return static_cast<double>(linear_to_srgb8(v)) / 255.0; };
  return {e(c.r), e(c.g), e(c.b), c.a};
}

std::string hex(render::Color c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", linear_to_srgb8(c.r), linear_to_srgb8(c.g), linear_to_srgb8(c.b));
  return buf;
}

cairo_surface_t* image_surface(const Image& im) {
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, im.width, im.height);
  if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(s);
    throw VectorError("vector: cannot make a " + std::to_string(im.width) + "x" + std::to_string(im.height) + " image");
  }
  cairo_surface_flush(s);
  unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int j = 0; j < im.height; ++j) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(j) * stride);
    for (int i = 0; i < im.width; ++i) {
      const float* p = im.pixel(i, j);
      const float a = std::clamp(p[3], 0.0f, 1.0f);
      // Straight linear colour, encoded, then premultiplied in the encoded space (Cairo's form).
      auto chan = [&](float v) {
        const float straight = a > 0 ? std::clamp(v / a, 0.0f, 1.0f) : 0.0f;
        return static_cast<std::uint32_t>(std::lround(linear_to_srgb8(straight) * a));
      };
      const std::uint32_t A = static_cast<std::uint32_t>(std::lround(a * 255));
      row[i] = (A << 24) | (chan(p[0]) << 16) | (chan(p[1]) << 8) | chan(p[2]);
    }
  }
  cairo_surface_mark_dirty(s);
  return s;
}

std::vector<unsigned char> png_bytes(const Image& im) {
  cairo_surface_t* s = image_surface(im);
  std::vector<unsigned char> out;
  auto write = [](void* closure, const unsigned char* data, unsigned int n) {
    auto* v = static_cast<std::vector<unsigned char>*>(closure);
    v->insert(v->end(), data, data + n);
    return CAIRO_STATUS_SUCCESS;
  };
  const cairo_status_t st = cairo_surface_write_to_png_stream(s, write, &out);
  cairo_surface_destroy(s);
  if (st != CAIRO_STATUS_SUCCESS) throw VectorError(std::string("vector: PNG encoding failed: ") + cairo_status_to_string(st));
  return out;
}

}  // namespace splinefig::vector::detail
