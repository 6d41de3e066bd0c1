// PDF through Cairo's PDF surface: the scene drawn in pixel units on a page of
// width * 72 / dpi points.
#include "raster.hpp"

#include <splinefig/renderer/text_outlines.hpp>
#include <splinefig/vector/vector.hpp>

#include <cairo-pdf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <ctime>
#include <exception>
#include <numbers>
#include <string>
#include <variant>

namespace splinefig::vector {
namespace {

using render::Vec2;

const cairo_user_data_key_t kLayerFaceKey{};

// How far inside its rectangle an image is placed, in output pixels (PdfWriter::image).
constexpr double kImageInset = 0.01;

// The invisible text layer: a Cairo user font (PDF Type 3) per face whose glyphs are the code
// points, each with the advance of its character in that DejaVu face and a declared ink box
// (so that Cairo writes the text at all) but no drawing. The string lands in the page's content
// stream, with a ToUnicode map from the clusters, and paints nothing.
struct LayerFace {
  render::TextStyle style;  // the face (family, weight, slant) at size 1: advances in ems
};

cairo_status_t empty_glyph(cairo_scaled_font_t* font, unsigned long glyph, cairo_t*, cairo_text_extents_t* extents) {
  try {
    const auto* face = static_cast<const LayerFace*>(
        cairo_font_face_get_user_data(cairo_scaled_font_get_font_face(font), &kLayerFaceKey));
    std::string ch;
    const auto c = static_cast<char32_t>(glyph);
    if (c < 0x80) ch += static_cast<char>(c);
    else if (c < 0x800) ch += {static_cast<char>(0xC0 | (c >> 6)), static_cast<char>(0x80 | (c & 0x3F))};
    else if (c < 0x10000)
      ch += {static_cast<char>(0xE0 | (c >> 12)), static_cast<char>(0x80 | ((c >> 6) & 0x3F)), static_cast<char>(0x80 | (c & 0x3F))};
    else
      ch += {static_cast<char>(0xF0 | (c >> 18)), static_cast<char>(0x80 | ((c >> 12) & 0x3F)),
             static_cast<char>(0x80 | ((c >> 6) & 0x3F)), static_cast<char>(0x80 | (c & 0x3F))};
    const double advance = render::measure_text(ch, face->style).width;
    // DejaVu's ascent and descent (0.928 and 0.236 em, rounded out): the box a viewer selects,
    // in the layer's mirrored font space (y up, see PdfWriter::text_layer).
    extents->x_bearing = 0;
    extents->y_bearing = -0.24;
    extents->width = advance > 0 ? advance : 0.001;
    extents->height = 1.17;
    extents->x_advance = advance;
    extents->y_advance = 0;
    return CAIRO_STATUS_SUCCESS;
  } catch (...) {
    return CAIRO_STATUS_USER_FONT_ERROR;
  }
}

// The user font faces of one document, by face.
class LayerFonts {
 public:
  ~LayerFonts() {
    for (cairo_font_face_t* f : faces_)
      if (f) cairo_font_face_destroy(f);
  }
  cairo_font_face_t* face(const render::TextStyle& style) {
    const std::size_t k = static_cast<std::size_t>(style.family) * 4 + (style.weight == render::FontWeight::Bold ? 2 : 0) +
                          (style.italic ? 1 : 0);
    if (!faces_[k]) {
      cairo_font_face_t* f = cairo_user_font_face_create();
      auto* data = new LayerFace{style};
      data->style.size = 1;
      data->style.halign = render::HAlign::Left;
      data->style.valign = render::VAlign::Baseline;
      data->style.angle = 0;
      cairo_font_face_set_user_data(f, &kLayerFaceKey, data, [](void* p) { delete static_cast<LayerFace*>(p); });
      cairo_user_font_face_set_render_glyph_func(f, empty_glyph);
      faces_[k] = f;
    }
    return faces_[k];
  }

 private:
  std::array<cairo_font_face_t*, 12> faces_{};
};

// The items drawn one by one on the page (std::visit); an item that draws nothing is skipped.
class PdfWriter {
 public:
  PdfWriter(cairo_t* cr, LayerFonts& fonts) : cr_(cr), fonts_(fonts) {}

  void operator()(const render::StrokeItem& it) {
    if (it.points.empty() || !(it.style.width > 0) || it.color.a <= 0) return;
    cairo_new_path(cr_);
    polyline(it.points, it.closed);
    stroke(it.style, it.color);
  }
  void operator()(const render::FillItem& it) { fill_polygon(it.contours, it.rule, it.color); }
  void operator()(const render::PathFillItem& it) { fill_path(*it.path, it.rule, it.color); }
  void operator()(const render::PathStrokeItem& it) {
    if (it.path->empty() || !(it.style.width > 0) || it.color.a <= 0) return;
    cairo_new_path(cr_);
    path(*it.path);
    stroke(it.style, it.color);
  }
  void operator()(const render::DiskItem& it) { fill_circle(it.centre, it.radius, it.color); }
  void operator()(const render::RingItem& it) {
    if (!(it.radius > 0) || !(it.style.width > 0) || it.color.a <= 0) return;
    cairo_new_path(cr_);
    cairo_arc(cr_, it.centre.x, it.centre.y, it.radius, 0, 2 * std::numbers::pi);
    cairo_close_path(cr_);
    stroke(it.style, it.color);
  }
  void operator()(const render::MarkerItem& it) {
    if (it.shape == render::Marker::Circle) return fill_circle(it.centre, 0.5 * it.size, it.color);
    if (!(it.size > 0)) return;
    fill_polygon({render::marker_polygon(it.shape, it.centre, it.size)}, render::FillRule::NonZero, it.color);
  }
  void operator()(const render::TextItem& it) {
    if (it.outline->empty() || it.style.color.a <= 0) return;
    fill_path(*it.outline, render::FillRule::NonZero, it.style.color);
    text_layer(it);
  }
  void operator()(const render::ImageItem& it) {
    const Image& im = *it.image;
    const Vec2 p0 = it.p0, p1 = it.p1;
    cairo_surface_t* s = detail::image_surface(im);
    cairo_save(cr_);
    // The image's corners a hundredth of a pixel inside its rectangle: a viewer that rounds
    // the image's device rectangle outwards (poppler at 96 dpi, where 1 pt is 4/3 px and an
    // edge at 48 pt lands at 63.99999 or 64.00001 px) would otherwise stretch a 256-px tile over
    // 257 pixels and resample every row and column; inset, it covers exactly its own pixels,
    // one image pixel to one device pixel, as the PNG shows it.
    const double ix = std::min(kImageInset, 0.25 * std::abs(p1.x - p0.x)) * (p1.x >= p0.x ? 1 : -1);
    const double iy = std::min(kImageInset, 0.25 * std::abs(p1.y - p0.y)) * (p1.y >= p0.y ? 1 : -1);
    cairo_translate(cr_, p0.x + ix, p0.y + iy);
    cairo_scale(cr_, (p1.x - p0.x - 2 * ix) / im.width, (p1.y - p0.y - 2 * iy) / im.height);
    cairo_set_source_surface(cr_, s, 0, 0);
    cairo_pattern_t* pat = cairo_get_source(cr_);
    cairo_pattern_set_filter(pat, it.sampling == render::Sampling::Nearest ? CAIRO_FILTER_NEAREST : CAIRO_FILTER_BILINEAR);
    cairo_pattern_set_extend(pat, CAIRO_EXTEND_PAD);
    cairo_new_path(cr_);
    cairo_rectangle(cr_, 0, 0, im.width, im.height);
    cairo_fill(cr_);
    cairo_restore(cr_);
    cairo_surface_destroy(s);
  }

 private:
  cairo_t* cr_;
  LayerFonts& fonts_;

  // The string over its outlines: each character at its pen position on the turned baseline,
  // one cluster per character, in the layer's font at the item's size.
  void text_layer(const render::TextItem& it) {
    const render::TextPlacement pl = render::text_placement(it.text, it.anchor, it.style);
    if (pl.chars.empty()) return;
    std::vector<cairo_glyph_t> glyphs;
    std::vector<cairo_text_cluster_t> clusters;
    for (const render::PlacedChar& c : pl.chars) {
      glyphs.push_back({c.code, c.x, 0});
      clusters.push_back({static_cast<int>(c.bytes), 1});
    }
    cairo_save(cr_);
    cairo_translate(cr_, pl.origin.x, pl.origin.y);
    cairo_rotate(cr_, -it.style.angle * std::numbers::pi / 180);
    cairo_set_font_face(cr_, fonts_.face(it.style));
    // The font space mirrored (y up): Cairo writes a Type 3 font's glyph space y down, and
    // poppler, which takes a glyph's up from the font's y axis, would read turned text the
    // wrong way round (a label turned 90 degrees as ")s(k" for "k(s)"). The glyphs draw
    // nothing, so the mirror shows nowhere.
    cairo_matrix_t m;
    cairo_matrix_init_scale(&m, it.style.size, -it.style.size);
    cairo_set_font_matrix(cr_, &m);
    cairo_set_source_rgb(cr_, 0, 0, 0);
    cairo_show_text_glyphs(cr_, it.text.data(), static_cast<int>(it.text.size()), glyphs.data(),
                           static_cast<int>(glyphs.size()), clusters.data(), static_cast<int>(clusters.size()),
                           static_cast<cairo_text_cluster_flags_t>(0));
    cairo_restore(cr_);
  }

  void fill_polygon(const std::vector<std::vector<Vec2>>& contours, render::FillRule rule, render::Color c) {
    if (c.a <= 0) return;
    cairo_new_path(cr_);
    for (const auto& ctr : contours)
      if (!ctr.empty()) polyline(ctr, true);
    fill(rule, c);
  }
  void fill_path(const render::Path& p, render::FillRule rule, render::Color c) {
    if (p.empty() || c.a <= 0) return;
    cairo_new_path(cr_);
    path(p);
    fill(rule, c);
  }
  void fill_circle(Vec2 ctr, double r, render::Color c) {
    if (!(r > 0) || c.a <= 0) return;
    cairo_new_path(cr_);
    cairo_arc(cr_, ctr.x, ctr.y, r, 0, 2 * std::numbers::pi);
    cairo_close_path(cr_);
    fill(render::FillRule::NonZero, c);
  }

  void polyline(std::span<const Vec2> pts, bool closed) {
    cairo_move_to(cr_, pts[0].x, pts[0].y);
    for (std::size_t i = 1; i < pts.size(); ++i) cairo_line_to(cr_, pts[i].x, pts[i].y);
    if (closed) cairo_close_path(cr_);
  }
  void path(const render::Path& p) {
    std::size_t k = 0;
    const auto& q = p.points();
    for (render::Path::Verb v : p.verbs()) {
      switch (v) {
        case render::Path::Verb::Move: cairo_move_to(cr_, q[k].x, q[k].y), ++k; break;
        case render::Path::Verb::Line: cairo_line_to(cr_, q[k].x, q[k].y), ++k; break;
        case render::Path::Verb::Cubic:
          cairo_curve_to(cr_, q[k].x, q[k].y, q[k + 1].x, q[k + 1].y, q[k + 2].x, q[k + 2].y);
          k += 3;
          break;
        case render::Path::Verb::Close: cairo_close_path(cr_); break;
      }
    }
  }
  void source(render::Color c) {
    const detail::Srgb s = detail::to_srgb(c);
    cairo_set_source_rgba(cr_, s.r, s.g, s.b, s.a);
  }
  void fill(render::FillRule rule, render::Color c) {
    source(c);
    cairo_set_fill_rule(cr_, rule == render::FillRule::EvenOdd ? CAIRO_FILL_RULE_EVEN_ODD : CAIRO_FILL_RULE_WINDING);
    cairo_fill(cr_);
  }
  void stroke(const render::StrokeStyle& st, render::Color c) {
    source(c);
    cairo_set_line_width(cr_, st.width);
    cairo_set_line_join(cr_, st.join == render::Join::Round   ? CAIRO_LINE_JOIN_ROUND
                             : st.join == render::Join::Bevel ? CAIRO_LINE_JOIN_BEVEL
                                                              : CAIRO_LINE_JOIN_MITER);
    cairo_set_miter_limit(cr_, st.miter_limit);
    cairo_set_line_cap(cr_, st.cap == render::Cap::Round    ? CAIRO_LINE_CAP_ROUND
                            : st.cap == render::Cap::Square ? CAIRO_LINE_CAP_SQUARE
                                                            : CAIRO_LINE_CAP_BUTT);
    if (!st.dashes.empty())
      cairo_set_dash(cr_, st.dashes.data(), static_cast<int>(st.dashes.size()), st.dash_offset);
    else
      cairo_set_dash(cr_, nullptr, 0, 0);
    cairo_stroke(cr_);
  }
};

std::string pdf_date(long long t) {
  const std::time_t tt = static_cast<std::time_t>(t);
  std::tm tm{};
  gmtime_r(&tt, &tm);
  char buf[40];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace

std::vector<unsigned char> to_pdf(const render::Scene& scene, const Options& o) {
  const double dpi = o.dpi > 0 ? o.dpi : 96.0;
  const double k = 72.0 / dpi;  // points per pixel
  std::vector<unsigned char> bytes;
  auto write = [](void* closure, const unsigned char* data, unsigned int n) {
    auto* v = static_cast<std::vector<unsigned char>*>(closure);
    v->insert(v->end(), data, data + n);
    return CAIRO_STATUS_SUCCESS;
  };
  cairo_surface_t* surface = cairo_pdf_surface_create_for_stream(write, &bytes, scene.width() * k, scene.height() * k);
  // The creation date is the given one, or none (Cairo leaves an empty one out), never the clock:
  // same scene, same bytes. 0 (SOURCE_DATE_EPOCH=0) is no date either, not 1970.
  const std::string date = o.date > 0 ? pdf_date(o.date) : std::string();
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATE_DATE, date.c_str());
  if (!o.title.empty()) cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, o.title.c_str());
  if (!o.creator.empty()) cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, o.creator.c_str());
  cairo_t* cr = cairo_create(surface);
  cairo_scale(cr, k, k);
  const render::Color bg = scene.background();
  if (bg.a > 0) {
    const detail::Srgb s = detail::to_srgb(bg);
    cairo_set_source_rgba(cr, s.r, s.g, s.b, s.a);
    cairo_paint(cr);
  }
  // An item the writer refuses (a clipped one: render::DrawError) ends the document first, then
  // leaves as itself, with its own type and kind.
  std::exception_ptr refused;
  LayerFonts fonts;  // after the context and surface are gone, which hold references to its faces
  try {
    PdfWriter w(cr, fonts);
    for (const render::DrawItem& item : detail::unclipped_items(scene)) std::visit(w, item);
  } catch (...) {
    refused = std::current_exception();
  }
  const cairo_status_t st = cairo_status(cr);
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const cairo_status_t sst = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (refused) std::rethrow_exception(refused);
  if (st != CAIRO_STATUS_SUCCESS || sst != CAIRO_STATUS_SUCCESS)
    throw VectorError(std::string("PDF: ") + cairo_status_to_string(st != CAIRO_STATUS_SUCCESS ? st : sst));
  return bytes;
}

}  // namespace splinefig::vector
