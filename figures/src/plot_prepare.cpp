// An axes prepared for layout: generated elements computed, curves built (see plot.hpp).
#include "plot.hpp"

namespace splinefig::figures::detail {

PreparedAxes prepare_axes(const AxesSpec& ax) {
  PreparedAxes out;
  out.axes = ax;
  out.axes.elements.clear();
  auto& elements = out.axes.elements;
  for (const PlotElement& e : ax.elements) {
    if (const auto* c = std::get_if<CurveElement>(&e)) {
      Points knots(2);
      for (Vec2 k : c->knots) knots.push_back(std::array<double, 2>{k.x, k.y});
      out.curves.emplace(elements.size(), make_curve(c->basis, knots, c->ends));
    }
    if (!is_generated(e)) {
      elements.push_back(e);
      continue;
    }
    for (GeneratedPart& part : generate(e)) {
      if (auto* g = std::get_if<GeneratedSeries>(&part)) {
        if (g->path) {
          g->series.points = rough_points(*g->path);
          out.paths.emplace_back(elements.size(), std::move(*g->path));
        }
        elements.push_back(std::move(g->series));
      } else {
        elements.push_back(std::move(std::get<ImageElement>(part)));
      }
    }
  }
  return out;
}

void sample_paths(PreparedAxes& prepared, const PixelMap& map, double tolerance) {
  for (const auto& [index, path] : prepared.paths)
    std::get<SeriesElement>(prepared.axes.elements[index]).points = sample_path(path, map, tolerance);
}

}  // namespace splinefig::figures::detail
