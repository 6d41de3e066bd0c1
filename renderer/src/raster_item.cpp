// Raster image items (see raster_item.hpp).
#include "raster_item.hpp"

#include <algorithm>
#include <cmath>

namespace splinefig::render::detail {

void composite_raster(const ImageItem& r, const Compositor& comp, Image& img, int r0, int r1) {
  const Image& src = *r.image;
  const bool nearest = r.sampling == Sampling::Nearest;
  const double x0 = r.p0.x, y0 = r.p0.y, x1 = r.p1.x, y1 = r.p1.y;
  const double xlo = std::min(x0, x1), xhi = std::max(x0, x1), ylo = std::min(y0, y1), yhi = std::max(y0, y1);
  // Clamped while still doubles: a rectangle may reach 1e14 px past the canvas.
  auto to_range = [](double v, int lo, int hi) { return static_cast<int>(std::clamp(v, double(lo), double(hi))); };
  const int ix0 = to_range(std::floor(xlo), 0, img.width), ix1 = to_range(std::ceil(xhi), 0, img.width);
  const int iy0 = to_range(std::floor(ylo), r0, r1), iy1 = to_range(std::ceil(yhi), r0, r1);
  if (nearest && x0 == std::floor(x0) && y0 == std::floor(y0) && x1 - x0 == src.width && y1 - y0 == src.height) {
    // Pixel for pixel (a layer, or one picture placed at whole pixels): each canvas pixel takes
    // the source pixel it covers, the one nearest sampling picks. A pixel with nothing in it
    // leaves the canvas as over would (p * c + px * 1 = px), so it is skipped.
    for (int y = iy0; y < iy1; ++y) {
      const float* s = src.pixel(0, y - static_cast<int>(y0));
      for (int x = ix0; x < ix1; ++x) {
        const float* p = s + 4 * static_cast<std::size_t>(x - static_cast<int>(x0));
        if (p[0] == 0 && p[1] == 0 && p[2] == 0 && p[3] == 0) continue;
        over(img.pixel(x, y), comp.paint_premultiplied(p, src.encoding), 1.0f);
      }
    }
    return;
  }
  auto fetch = [&](int x, int y, int k) {
    x = std::clamp(x, 0, src.width - 1);
    y = std::clamp(y, 0, src.height - 1);
    return src.at(x, y, k);
  };
  for (int y = iy0; y < iy1; ++y) {
    // Pixels of the canvas whose centre lies inside the rectangle.
    const double cy = y + 0.5;
    if (cy < ylo || cy >= yhi) continue;
    const double sy = (cy - y0) / (y1 - y0) * src.height;
    for (int x = ix0; x < ix1; ++x) {
      const double cx = x + 0.5;
      if (cx < xlo || cx >= xhi) continue;
      const double sx = (cx - x0) / (x1 - x0) * src.width;
      float s[4];
      if (nearest) {
        const int px = static_cast<int>(std::floor(sx)), py = static_cast<int>(std::floor(sy));
        for (int k = 0; k < 4; ++k) s[k] = fetch(px, py, k);
      } else {
        const double fx = sx - 0.5, fy = sy - 0.5;
        const int px = static_cast<int>(std::floor(fx)), py = static_cast<int>(std::floor(fy));
        const float tx = static_cast<float>(fx - px), ty = static_cast<float>(fy - py);
        for (int k = 0; k < 4; ++k)
          s[k] = (1 - ty) * ((1 - tx) * fetch(px, py, k) + tx * fetch(px + 1, py, k)) +
                 ty * ((1 - tx) * fetch(px, py + 1, k) + tx * fetch(px + 1, py + 1, k));
      }
      over(img.pixel(x, y), comp.paint_premultiplied(s, src.encoding), 1.0f);
    }
  }
}

}  // namespace splinefig::render::detail
