// A whole figure: title, pixel-space items and axes panels in document order.
#include <splinefig/figures/figure.hpp>

#include "plot.hpp"

#include <cmath>

namespace splinefig::figures {

AxisMap AxesInfo::x_map() const { return {x_scale, x_range[0], x_range[1], pixel_box[0], pixel_box[2]}; }
AxisMap AxesInfo::y_map() const { return {y_scale, y_range[0], y_range[1], pixel_box[3], pixel_box[1]}; }

void check_scaled_canvas(const FigureSpec& spec, double scale, const std::string& what) {
  if (!(scale > 0) || !std::isfinite(scale)) throw SpecFileError(what + ": the scale must be a positive number");
  double w = std::round(spec.canvas.width * scale), h = std::round(spec.canvas.height * scale);
  if (w < 1 || h < 1) throw SpecFileError(what + ": the scaled canvas has no pixels");
  if (w > kMaxCanvasSide || h > kMaxCanvasSide)
    throw SpecFileError(what + ": the scaled canvas " + std::to_string(static_cast<long long>(w)) + "x" +
                        std::to_string(static_cast<long long>(h)) + " is larger than " + std::to_string(kMaxCanvasSide) +
                        " px a side");
  if (w * h > static_cast<double>(kMaxCanvasPixels))
    throw SpecFileError(what + ": the scaled canvas has more than 2^28 pixels");
}

namespace {

using namespace detail;

FigureInfo build(const FigureSpec& spec, double scale, Painter& p) {
  FigureInfo info;
  info.name = spec.name;
  info.title = spec.title;
  info.caption = spec.caption;
  info.width = static_cast<int>(std::round(spec.canvas.width * scale));
  info.height = static_cast<int>(std::round(spec.canvas.height * scale));
  const Guides g;
  const double W = spec.canvas.width, H = spec.canvas.height;
  double top = spec.layout.margin;
  if (spec.show_title && !spec.title.empty()) {
    Font tf{spec.title_size, *render::parse_hex_color("#222222"), true};
    p.text(spec.title, {0.5 * W, spec.layout.margin}, tf, {render::HAlign::Center, render::VAlign::Top});
    top += spec.title_size * 1.25 + 10;
  }
  // The panel grid fills the rest of the canvas.
  const Layout& L = spec.layout;
  const double gw = (W - 2 * L.margin - (L.cols - 1) * L.spacing) / L.cols;
  const double gh = (H - top - L.margin - (L.rows - 1) * L.spacing) / L.rows;
  Occupancy occ(spec.canvas.width, spec.canvas.height);
  for (const Item& item : spec.items) {
    std::visit(
        [&](const auto& it) {
          using T = std::decay_t<decltype(it)>;
          if constexpr (std::is_same_v<T, PolylineItem>) {
            p.stroke(it.points, it.closed, it.pen.style, it.pen.color);
          } else if constexpr (std::is_same_v<T, PolygonItem>) {
            p.fill(it.contours, it.rule, it.color);
          } else if constexpr (std::is_same_v<T, CircleItem>) {
            p.circle(it.centre, it.radius, it.fill, it.stroke);
          } else if constexpr (std::is_same_v<T, MarkerItem>) {
            for (Vec2 q : it.points) p.marker(it.shape, q, it.size, it.color);
          } else if constexpr (std::is_same_v<T, TextItem>) {
            p.text(it.text, it.at, it.font, it.anchor);
          } else if constexpr (std::is_same_v<T, ImageItem>) {
            Vec2 size = it.size;
            if (!it.has_size) {
              // Own size: inline data knows it; files are read when painted, so ask now.
              size = {static_cast<double>(it.raster.width), static_cast<double>(it.raster.height)};
              if (!it.raster.file.empty()) size = raster_size(it.raster);
            }
            p.image(it.raster, it.at.x, it.at.y, it.at.x + size.x, it.at.y + size.y);
          } else if constexpr (std::is_same_v<T, AxesSpec>) {
            Rect cell{0, 0, W, H};
            if (it.cell) {
              int r = (*it.cell)[0], c = (*it.cell)[1];
              cell.left = L.margin + c * (gw + L.spacing);
              cell.right = cell.left + gw;
              cell.top = top + r * (gh + L.spacing);
              cell.bottom = cell.top + gh;
            }
            PreparedAxes prepared = prepare_axes(it);
            const AxesSpec& ax = prepared.axes;
            Panel panel = layout_panel(prepared, cell, p, g);
            sample_paths(prepared, panel.map, 0.05 / scale);
            draw_under(ax, panel, p, g);
            AxesInfo ai;
            std::vector<Entry> entries;
            draw_elements(prepared, panel, p, occ, ai.series, entries);
            draw_over(ax, panel, cell, p, g);
            draw_legend(ax, panel, entries, p, occ, g);
            ai.pixel_box = {panel.box.left * scale, panel.box.top * scale, panel.box.right * scale,
                            panel.box.bottom * scale};
            ai.x_range = panel.x_range;
            ai.y_range = panel.y_range;
            ai.x_scale = it.x.scale;
            ai.y_scale = it.y.scale;
            for (const auto& t : panel.x_ticks) ai.x_ticks.push_back(t.value);
            for (const auto& t : panel.y_ticks) ai.y_ticks.push_back(t.value);
            info.axes.push_back(std::move(ai));
          }
        },
        item);
  }
  return info;
}

}  // namespace

FigureInfo layout_figure(const FigureSpec& spec, double scale) {
  check_scaled_canvas(spec, scale, spec.path);
  Painter p(scale);
  return build(spec, scale, p);
}

RenderedFigure render_figure(const FigureSpec& spec, const RenderOptions& options) {
  check_scaled_canvas(spec, options.scale, spec.path);
  Painter p(options.scale);
  RenderedFigure out;
  out.info = build(spec, options.scale, p);
  out.image = paint(p, out.info.width, out.info.height, spec.canvas.background, pixel_filter(spec.canvas.filter),
                    options.threads);
  return out;
}

}  // namespace splinefig::figures
