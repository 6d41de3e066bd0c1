// An axes prepared for layout: generated elements computed, curves built (see panel.hpp).
#include "panel.hpp"

namespace splinefig::figures::detail {

namespace {

// A filter curve without a range of its own spans the axes' x range when that is given (zero
// outside the support, like the function it is); otherwise its support.
PlotElement over_axis(const PlotElement& e, const AxesSpec& ax) {
  const auto* f = std::get_if<FilterCurveElement>(&e);
  if (!f || f->range || !ax.x.range) return e;
  FilterCurveElement spanning = *f;
  spanning.range = ax.x.range;
  return spanning;
}

}  // namespace

PreparedAxes prepare_axes(const AxesSpec& ax) {
  PreparedAxes out;
  out.axes = ax;
  out.axes.elements.clear();
  auto& elements = out.axes.elements;
  auto& origins = out.axes.element_origins;
  origins.clear();
  for (std::size_t i = 0; i < ax.elements.size(); ++i) {
    const PlotElement& e = ax.elements[i];
    const SpecLocation origin = i < ax.element_origins.size() ? ax.element_origins[i] : ax.where.with_key("axes");
    naming_origin(origin, [&] {
      if (const auto* c = std::get_if<CurveElement>(&e)) {
        Points knots(2);
        for (Vec2 k : c->knots) knots.push_back(std::array<double, 2>{k.x, k.y});
        out.curves.emplace(elements.size(), make_curve(c->basis, knots, c->ends));
      }
      if (!is_generated(e)) {
        elements.push_back(e);
        return;
      }
      for (GeneratedPart& part : generate(over_axis(e, ax))) {
        if (auto* g = std::get_if<GeneratedSeries>(&part)) {
          out.generated.emplace_back(elements.size(), origin);
          if (g->path) {
            g->series.points = rough_points(*g->path);
            g->series.bezier = std::move(g->path->bezier);  // the path keeps only what sampling needs
            out.paths.emplace_back(elements.size(), std::move(*g->path));
          }
          elements.push_back(std::move(g->series));
        } else {
          elements.push_back(std::move(std::get<ImageElement>(part)));
        }
      }
    });
    origins.resize(elements.size(), origin);
  }
  return out;
}

void sample_paths(PreparedAxes& prepared, const PixelMap& map, double tolerance) {
  for (const auto& entry : prepared.paths) {
    const std::size_t index = entry.first;
    const auto& path = entry.second;
    const auto& origins = prepared.axes.element_origins;
    naming_origin(index < origins.size() ? origins[index] : prepared.axes.where, [&] {
      std::get<SeriesElement>(prepared.axes.elements[index]).points = sample_path(path, map, tolerance);
    });
  }
  const bool log_x = prepared.axes.x.scale == Scale::Log, log_y = prepared.axes.y.scale == Scale::Log;
  if (!log_x && !log_y) return;
  for (const auto& [index, where] : prepared.generated)
    for (Vec2 q : std::get<SeriesElement>(prepared.axes.elements[index]).points) {
      if (log_y && !(q.y > 0)) throw SpecFileError(where, "a log y axis needs positive y data");
      if (log_x && !(q.x > 0)) throw SpecFileError(where, "a log x axis needs positive x data");
    }
}

}  // namespace splinefig::figures::detail
