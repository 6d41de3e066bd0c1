#pragma once
// In-process checks of where a black element's pixels are: a spec rendered with render_figure()
// and the ink (1 - green, linear light) near a data point of its first axes.
#include <splinefig/figures/figure.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace figtest {

// The spec's figure at 1x on one thread, without its title.
inline splinefig::figures::RenderedFigure render_text_spec(const std::string& text) {
  splinefig::figures::FigureSpec spec = splinefig::figures::parse_spec(text, "ink.toml");
  spec.show_title = false;
  return splinefig::figures::render_figure(spec, {1, 1});
}

// The darkest ink within r px of data (x, y) on axes `axes`.
inline double ink_near(const splinefig::figures::RenderedFigure& f, double x, double y, int r = 2, std::size_t axes = 0) {
  const splinefig::figures::AxesInfo& a = f.info.axes.at(axes);
  const int px = static_cast<int>(std::floor(a.x_map().to_pixel(x))), py = static_cast<int>(std::floor(a.y_map().to_pixel(y)));
  double best = 0;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) best = std::max(best, 1.0 - f.image.pixel(px + dx, py + dy)[1]);
  return best;
}

}  // namespace figtest
