// A whole figure: title, pixel-space items and axes panels in document order.
#include <splinefig/figures/figure.hpp>

#include "layout/caption_text.hpp"
#include "paint/draw.hpp"
#include "text/rich_text.hpp"

#include <cmath>

namespace splinefig::figures {

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

// The layout grid's cells, below the figure title.
struct PanelGrid {
  double left, top, cell_width, cell_height, spacing;
  double canvas_width, canvas_height;
  // The panel's cell, or the whole canvas for a panel placed by its own `box`.
  Rect cell(const AxesSpec& ax) const {
    if (!ax.cell) return {0, 0, canvas_width, canvas_height};
    const int r = (*ax.cell)[0], c = (*ax.cell)[1];
    const double x = left + c * (cell_width + spacing), y = top + r * (cell_height + spacing);
    return {x, y, x + cell_width, y + cell_height};
  }
};

// ---- Pixel-space items ------------------------------------------------------------------

void draw_item(const PolylineItem& it, Painter& p) { p.stroke(it.points, it.closed, it.pen.style, it.pen.color); }
void draw_item(const PolygonItem& it, Painter& p) { p.fill(it.contours, it.rule, it.color); }
void draw_item(const CircleItem& it, Painter& p) { p.circle(it.centre, it.radius, it.fill, it.stroke); }
void draw_item(const MarkerItem& it, Painter& p) {
  for (Vec2 q : it.points) p.marker(it.shape, q, it.size, it.color);
}
void draw_item(const TextItem& it, Painter& p) { p.text(it.text, it.at, it.font, it.anchor); }
void draw_item(const ImageItem& it, Painter& p) {
  Vec2 size = it.size;
  if (!it.has_size) {
    // Own size: inline data knows it; files are read when painted, so ask now.
    size = {static_cast<double>(it.raster.width), static_cast<double>(it.raster.height)};
    if (!it.raster.file.empty()) size = raster_size(it.raster);
  }
  p.image(it.raster, it.at.x, it.at.y, it.at.x + size.x, it.at.y + size.y);
}

// ---- Axes -------------------------------------------------------------------------------

// Lays one panel out in its cell and draws it: generated elements computed, the box, ranges
// and ticks, curves sampled at the output scale, then guides under, data, guides over, legend.
// One attempt: `require_free` as draw_legend takes it; `*crowded` set when the legend found no
// free spot (then the panel is drawn without it, for the caller to draw again).
AxesInfo draw_panel(PreparedAxes& prepared, const AxesSpec& spec, const Rect& cell, const Rect& canvas, double scale,
                    Painter& p, Occupancy& occ, const Guides& g, bool require_free, bool* crowded) {
  const AxesSpec& ax = prepared.axes;
  // A text the layout measures and the renderer refuses (bad markup, too many combining
  // marks) is named as when it is drawn: FILE:LINE: axes.
  const Panel panel = [&] {
    try {
      return layout_panel(prepared, cell, canvas.width(), canvas.height(), p, g);
    } catch (const KeyError&) {
      throw;
    } catch (const LayoutRefused&) {
      throw;
    } catch (const SpecFileError&) {
      throw;
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      throw SpecFileError(ax.where.with_key("axes"), e.what());
    }
  }();
  sample_paths(prepared, panel.map, 0.05 / scale);
  draw_under(ax, panel, p, g);
  AxesInfo info;
  std::vector<Entry> entries;
  const std::size_t first_op = p.ops().size();
  draw_elements(prepared, panel, p, occ, info.series, entries, info.data_ink, g);
  const std::size_t end_op = p.ops().size();
  draw_over(ax, panel, p, g);
  mark_inset_sources(ax, panel, occ);
  const std::optional<Rect> legend = draw_legend(ax, panel, entries, p, occ, g, require_free, crowded);
  if (crowded && *crowded) return info;
  draw_insets(prepared, panel, p, occ, g, info.insets);
  auto add_box = [&](const std::string& what, const Rect& r) {
    info.text_boxes.push_back({what, {r.left * scale, r.top * scale, r.right * scale, r.bottom * scale}});
  };
  for (const auto* v : {&panel.x_tick_labels, &panel.y_tick_labels, &panel.labels})
    for (const PlacedText& t : *v)
      if (!t.text.empty()) add_box(t.what, t.rect);
  if (legend) add_box("legend", *legend);
  // The elements' texts (inline labels, [[axes.text]], annotations) stay inside the canvas and
  // clear of the guides' texts and the legend: an error naming the element if not.
  const std::size_t guide_boxes = info.text_boxes.size();
  for (std::size_t i = first_op; i < end_op; ++i) {
    const auto* t = std::get_if<TextOp>(&p.ops()[i]);
    if (!t) continue;
    const Rect r = text_rect(p.measure(t->text, t->font), t->at, t->anchor, t->angle);
    std::string why;
    if (r.left < canvas.left || r.top < canvas.top || r.right > canvas.right || r.bottom > canvas.bottom)
      why = "would leave the canvas";
    const Rect s = {r.left * scale, r.top * scale, r.right * scale, r.bottom * scale};
    for (std::size_t j = 0; j < guide_boxes && why.empty(); ++j) {
      const auto& b = info.text_boxes[j].box;
      if (rects_meet(s, {b[0], b[1], b[2], b[3]})) why = "would meet the axes' " + info.text_boxes[j].what;
    }
    if (!why.empty()) {
      const SpecLocation& origin = p.origin_of(i);
      throw SpecFileError(origin.empty() ? spec.where.with_key("axes") : origin, "its text " + why + " (the canvas " +
                          std::to_string(static_cast<long long>(canvas.width())) + "x" +
                          std::to_string(static_cast<long long>(canvas.height())) + ")");
    }
    add_box("text", r);
  }
  info.pixel_box = {panel.box.left * scale, panel.box.top * scale, panel.box.right * scale, panel.box.bottom * scale};
  info.x_range = panel.x_range;
  info.y_range = panel.y_range;
  info.x_scale = ax.x.scale;
  info.y_scale = ax.y.scale;
  for (const auto& t : panel.x_ticks) info.x_ticks.push_back(t.value);
  for (const auto& t : panel.y_ticks) info.y_ticks.push_back(t.value);
  return info;
}

// Lays one panel out in its cell and draws it (draw_panel). A legend that finds no spot in the
// box free of data goes outside it, on the right (the box narrows for it), when the panel is
// laid out in a cell and the canvas has room; else it takes the spot that covers least.
AxesInfo draw_axes(const AxesSpec& spec, const Rect& cell, const Rect& canvas, double scale, Painter& p, Occupancy& occ,
                   const Guides& g) {
  PreparedAxes prepared = prepare_axes(spec);
  const LegendPlace asked = prepared.axes.legend;
  const bool may_move = !prepared.axes.box && asked != LegendPlace::None && asked != LegendPlace::OutsideRight &&
                        !legend_labels(prepared.axes).empty();
  if (!may_move) return draw_panel(prepared, spec, cell, canvas, scale, p, occ, g, false, nullptr);
  const std::size_t mark = p.ops().size();
  const Occupancy before = occ;
  bool crowded = false;
  AxesInfo info = draw_panel(prepared, spec, cell, canvas, scale, p, occ, g, true, &crowded);
  if (!crowded) return info;
  p.truncate(mark);
  occ = before;
  prepared.axes.legend = LegendPlace::OutsideRight;
  try {
    return draw_panel(prepared, spec, cell, canvas, scale, p, occ, g, false, nullptr);
  } catch (const LayoutRefused&) {
    // No room beside the box: inside after all, where it covers least.
  }
  p.truncate(mark);
  occ = before;
  prepared.axes.legend = asked;
  return draw_panel(prepared, spec, cell, canvas, scale, p, occ, g, false, nullptr);
}

// The whole figure into the painter's display list: the title, then the items in document
// order (later ones over earlier ones).
FigureInfo build(const FigureSpec& spec, double scale, Painter& p) {
  FigureInfo info;
  info.name = spec.name;
  info.title = plain_text(spec.title);  // index.json and the gallery show it as plain text
  info.caption = caption_text(spec);  // its {=name} fields computed from the elements' data
  info.source = spec.source;
  info.pixel_exact = spec.pixel_exact;
  info.width = static_cast<int>(std::round(spec.canvas.width * scale));
  info.height = static_cast<int>(std::round(spec.canvas.height * scale));
  const Guides g(spec.sizes);
  const double W = spec.canvas.width, H = spec.canvas.height;
  const Layout& L = spec.layout;
  double top = L.margin;
  if (spec.show_title && !spec.title.empty()) {
    Font tf{spec.sizes.title, *render::parse_hex_color("#1a1a1a"), true, std::nullopt};
    const SpecLocation origin = spec.title_origin.empty() ? SpecLocation{spec.path, 0, "title"} : spec.title_origin;
    p.set_origin(origin);
    // A title wider than the canvas's margins shrinks to fit them, else to fit the canvas (not
    // below 9 px); one that still does not fit across is refused. (A size the renderer refuses
    // at the output scale is left to it.)
    render::TextExtent e;
    naming_origin(origin, [&] { e = p.measure(spec.title, tf); });
    if (tf.size * scale <= kMaxFontSize) {
      const double full = e.width, full_size = tf.size;
      auto shrink_to = [&](double room) {
        tf.size = full_size;
        e = p.measure(spec.title, tf);
        if (e.width <= room) return true;
        tf.size = std::min(full_size, std::floor(2 * full_size * room / e.width) / 2);
        while (tf.size >= 9 && (e = p.measure(spec.title, tf)).width > room) tf.size -= 0.5;
        return tf.size >= 9 && e.width <= room;
      };
      if (!shrink_to(W - 2 * std::max(0.0, L.margin)) && !shrink_to(W)) {
        const auto n = [](double v) { return std::to_string(static_cast<long long>(std::ceil(std::max(0.0, v) - 1e-9))); };
        throw SpecFileError(origin, "the canvas " + n(W) + "x" + n(H) + " leaves " + n(W) +
                            " px across for the title; it needs at least " + n(full * 9 / full_size) +
                            " px (its text at 9 px), or show_title = false");
      }
    }
    p.text(spec.title, {0.5 * W, L.margin}, tf, {render::HAlign::Center, render::VAlign::Top});
    top += spec.sizes.title * 1.25 + 10;
  }
  // The panel grid fills the rest of the canvas.
  const PanelGrid grid{L.margin,
                       top,
                       (W - 2 * L.margin - (L.cols - 1) * L.spacing) / L.cols,
                       (H - top - L.margin - (L.rows - 1) * L.spacing) / L.rows,
                       L.spacing,
                       W,
                       H};
  Occupancy occ(spec.canvas.width, spec.canvas.height);
  for (std::size_t i = 0; i < spec.items.size(); ++i) {
    const SpecLocation origin = i < spec.item_origins.size() ? spec.item_origins[i] : SpecLocation{spec.path, 0, ""};
    p.set_origin(origin);
    naming_origin(origin, [&] {
      std::visit(
          [&](const auto& it) {
            if constexpr (std::is_same_v<std::decay_t<decltype(it)>, AxesSpec>)
              info.axes.push_back(draw_axes(it, grid.cell(it), {0, 0, W, H}, scale, p, occ, g));
            else
              draw_item(it, p);
          },
          spec.items[i]);
    });
  }
  return info;
}

}  // namespace

FigureInfo layout_figure(const FigureSpec& spec, double scale) {
  check_scaled_canvas(spec, scale, spec.path);
  Painter p(scale, spec.font_family);
  return build(spec, scale, p);
}

FigureScene figure_scene(const FigureSpec& spec, double scale) {
  check_scaled_canvas(spec, scale, spec.path);
  Painter p(scale, spec.font_family);
  FigureInfo info = build(spec, scale, p);
  render::Scene scene = scene_of(p, info.width, info.height, spec.canvas.background, spec.canvas.filter, spec.canvas.blend,
                                spec.canvas.coverage_tolerance);
  render::Scene raster =
      scene_of(p, info.width, info.height, spec.canvas.background, spec.canvas.filter, spec.canvas.blend,
               spec.canvas.coverage_tolerance, true);
  return {std::move(scene), std::move(info), std::move(raster)};
}

RenderedFigure render_figure(const FigureSpec& spec, const RenderOptions& options) {
  FigureScene fs = figure_scene(spec, options.scale);
  RenderedFigure out;
  out.image = render::rasterize(fs.raster, options.threads);
  out.info = std::move(fs.info);
  return out;
}

}  // namespace splinefig::figures
