// SVG written directly: one element per scene item, numbers to 1/1000 px, no styles or
// definitions that the picture does not need (docs/vector.md says why not Cairo's SVG surface).
#include "raster.hpp"

#include <splinefig/renderer/text_outlines.hpp>
#include <splinefig/vector/vector.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <string>
#include <variant>

namespace splinefig::vector {
namespace {

using render::Vec2;

// Shortest decimal of v to 3 places ("12.5", "-0.001", "3").
void num(std::string& out, double v) {
  char buf[40];
  double r = std::round(v * 1000) / 1000;
  if (r == 0) r = 0;  // no "-0"
  int n = std::snprintf(buf, sizeof buf, "%.3f", r);
  while (n > 0 && buf[n - 1] == '0') --n;
  if (n > 0 && buf[n - 1] == '.') --n;
  out.append(buf, static_cast<std::size_t>(n));
}

void point(std::string& out, Vec2 p) {
  num(out, p.x);
  out += ' ';
  num(out, p.y);
}

const char* base64_chars = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
std::string base64(const std::vector<unsigned char>& in) {
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < in.size(); i += 3) {
    const unsigned v = (in[i] << 16) | ((i + 1 < in.size() ? in[i + 1] : 0) << 8) | (i + 2 < in.size() ? in[i + 2] : 0);
    out += base64_chars[(v >> 18) & 63];
    out += base64_chars[(v >> 12) & 63];
    out += i + 1 < in.size() ? base64_chars[(v >> 6) & 63] : '=';
    out += i + 2 < in.size() ? base64_chars[v & 63] : '=';
  }
  return out;
}

// One element per item (std::visit), none for an item that draws nothing.
class SvgWriter {
 public:
  std::string out;

  void operator()(const render::StrokeItem& it) {
    if (it.points.empty() || !(it.style.width > 0) || it.color.a <= 0) return;
    out += "<path d=\"";
    polyline(it.points, it.closed);
    out += "\" fill=\"none\"";
    stroke_attributes(it.style, it.color);
    out += "/>\n";
  }
  void operator()(const render::FillItem& it) { fill_polygon(it.contours, it.rule, it.color); }
  void operator()(const render::PathFillItem& it) {
    if (it.path->empty() || it.color.a <= 0) return;
    out += "<path d=\"";
    path(*it.path);
    out += "\"";
    fill_attributes(it.rule, it.color);
    out += "/>\n";
  }
  void operator()(const render::PathStrokeItem& it) {
    if (it.path->empty() || !(it.style.width > 0) || it.color.a <= 0) return;
    out += "<path d=\"";
    path(*it.path);
    out += "\" fill=\"none\"";
    stroke_attributes(it.style, it.color);
    out += "/>\n";
  }
  void operator()(const render::DiskItem& it) { fill_circle(it.centre, it.radius, it.color); }
  void operator()(const render::RingItem& it) {
    if (!(it.radius > 0) || !(it.style.width > 0) || it.color.a <= 0) return;
    circle(it.centre, it.radius);
    out += " fill=\"none\"";
    stroke_attributes(it.style, it.color);
    out += "/>\n";
  }
  void operator()(const render::MarkerItem& it) {
    if (it.shape == render::Marker::Circle) return fill_circle(it.centre, 0.5 * it.size, it.color);
    if (!(it.size > 0)) return;
    fill_polygon({render::marker_polygon(it.shape, it.centre, it.size)}, render::FillRule::NonZero, it.color);
  }
  // The glyph outlines (what is seen, hidden from screen readers), and the string in an
  // invisible <text> laid over them (what is searched, selected and read aloud).
  void operator()(const render::TextItem& it) {
    if (it.outline->empty() || it.style.color.a <= 0) return;
    out += "<path aria-hidden=\"true\" d=\"";
    path(*it.outline);
    out += "\"";
    fill_attributes(render::FillRule::NonZero, it.style.color);
    out += "/>\n";
    text_layer(it);
  }
  // The invisible text still open, written before any other item and at the end.
  void flush() {
    if (text_.empty()) return;
    out += text_;
    out += "</text>\n";
    text_.clear();
  }
  void operator()(const render::ImageItem& it) {
    // The image's own pixels, mapped onto the rectangle (p0 is the image's top-left corner).
    const Image& im = *it.image;
    out += "<image width=\"" + std::to_string(im.width) + "\" height=\"" + std::to_string(im.height) +
           "\" preserveAspectRatio=\"none\" transform=\"matrix(";
    num(out, (it.p1.x - it.p0.x) / im.width);
    out += " 0 0 ";
    num(out, (it.p1.y - it.p0.y) / im.height);
    out += ' ';
    point(out, it.p0);
    out += ")\"";
    if (it.sampling == render::Sampling::Nearest) out += " image-rendering=\"optimizeSpeed\" style=\"image-rendering:pixelated\"";
    out += " href=\"data:image/png;base64," + base64(detail::png_bytes(im)) + "\"/>\n";
  }

 private:
  void fill_polygon(const std::vector<std::vector<Vec2>>& contours, render::FillRule rule, render::Color c) {
    if (c.a <= 0) return;
    std::string d;
    std::swap(d, out);
    for (const auto& ctr : contours)
      if (!ctr.empty()) polyline(ctr, true);
    std::swap(d, out);
    if (d.empty()) return;
    out += "<path d=\"" + d + "\"";
    fill_attributes(rule, c);
    out += "/>\n";
  }
  void fill_circle(Vec2 ctr, double r, render::Color c) {
    if (!(r > 0) || c.a <= 0) return;
    circle(ctr, r);
    fill_attributes(render::FillRule::NonZero, c);
    out += "/>\n";
  }
  void polyline(std::span<const Vec2> pts, bool closed) {
    for (std::size_t i = 0; i < pts.size(); ++i) {
      out += i == 0 ? "M" : "L";
      point(out, pts[i]);
    }
    if (closed) out += "Z";
  }
  void path(const render::Path& p) {
    std::size_t k = 0;
    const auto& pts = p.points();
    for (render::Path::Verb v : p.verbs()) {
      switch (v) {
        case render::Path::Verb::Move: out += "M"; point(out, pts[k++]); break;
        case render::Path::Verb::Line: out += "L"; point(out, pts[k++]); break;
        case render::Path::Verb::Cubic:
          out += "C";
          point(out, pts[k]), out += ' ', point(out, pts[k + 1]), out += ' ', point(out, pts[k + 2]);
          k += 3;
          break;
        case render::Path::Verb::Close: out += "Z"; break;
      }
    }
  }
  // The open <text>: its angle and where its last run ends, in its frame (the canvas turned
  // by -angle about the origin, so that the baseline runs along x).
  std::string text_;
  double text_angle_ = 0;
  Vec2 text_end_;

  // One run of a label: a <tspan> at the run's pen origin, in the run's face and size, as wide as
  // its outlines (textLength), fully transparent. A run that starts where the previous one ended
  // (the rich-text runs of one label: a subscript, an italic letter) continues its <text>, so a
  // label is one string to search and read.
  void text_layer(const render::TextItem& it) {
    const render::TextPlacement pl = render::text_placement(it.text, it.anchor, it.style);
    if (pl.chars.empty()) return;
    const double a = it.style.angle * std::numbers::pi / 180;
    const double c = std::cos(a), sn = std::sin(a);
    // Canvas (x, y) = (c u + sn v, -sn u + c v) for frame (u, v): SVG's rotate(-angle).
    const Vec2 f{c * pl.origin.x - sn * pl.origin.y, sn * pl.origin.x + c * pl.origin.y};
    const double tol = 1e-6 * std::max(1.0, it.style.size);
    if (text_.empty() || it.style.angle != text_angle_ || std::abs(f.x - text_end_.x) > tol) {
      flush();
      text_.assign("<text fill-opacity=\"0\" xml:space=\"preserve\"");
      if (it.style.angle != 0) {
        text_ += " transform=\"rotate(";
        std::swap(text_, out);
        num(out, -it.style.angle);
        std::swap(text_, out);
        text_ += ")\"";
      }
      text_ += ">";
      text_angle_ = it.style.angle;
    }
    text_end_ = {f.x + pl.width, f.y};
    std::swap(text_, out);
    out += "<tspan x=\"";
    num(out, f.x);
    out += "\" y=\"";
    num(out, f.y);
    out += "\" font-family=\"";
    out += it.style.family == render::FontFamily::Serif  ? "DejaVu Serif, serif"
           : it.style.family == render::FontFamily::Mono ? "DejaVu Sans Mono, monospace"
                                                         : "DejaVu Sans, sans-serif";
    out += "\" font-size=\"";
    num(out, it.style.size);
    out += "\"";
    if (it.style.weight == render::FontWeight::Bold) out += " font-weight=\"bold\"";
    if (it.style.italic) out += " font-style=\"italic\"";
    if (pl.width > 0) {
      out += " textLength=\"";
      num(out, pl.width);
      out += "\" lengthAdjust=\"spacingAndGlyphs\"";
    }
    out += '>';
    out += xml_escape(it.text);
    out += "</tspan>";
    std::swap(text_, out);
  }

  void circle(Vec2 c, double r) {
    out += "<circle cx=\"";
    num(out, c.x);
    out += "\" cy=\"";
    num(out, c.y);
    out += "\" r=\"";
    num(out, r);
    out += "\"";
  }
  void colour(const char* what, render::Color c) {
    out += std::string(" ") + what + "=\"" + detail::hex(c) + "\"";
    if (c.a < 1) {
      out += std::string(" ") + what + "-opacity=\"";
      num(out, c.a);
      out += "\"";
    }
  }
  void fill_attributes(render::FillRule rule, render::Color c) {
    if (detail::hex(c) != "#000000" || c.a < 1) colour("fill", c);
    if (rule == render::FillRule::EvenOdd) out += " fill-rule=\"evenodd\"";
  }
  void stroke_attributes(const render::StrokeStyle& st, render::Color c) {
    colour("stroke", c);
    if (st.width != 1) {
      out += " stroke-width=\"";
      num(out, st.width);
      out += "\"";
    }
    if (st.join == render::Join::Round) out += " stroke-linejoin=\"round\"";
    if (st.join == render::Join::Bevel) out += " stroke-linejoin=\"bevel\"";
    if (st.join == render::Join::Miter && st.miter_limit != 4) {
      out += " stroke-miterlimit=\"";
      num(out, st.miter_limit);
      out += "\"";
    }
    if (st.cap == render::Cap::Round) out += " stroke-linecap=\"round\"";
    if (st.cap == render::Cap::Square) out += " stroke-linecap=\"square\"";
    if (!st.dashes.empty()) {
      out += " stroke-dasharray=\"";
      for (std::size_t i = 0; i < st.dashes.size(); ++i) {
        if (i) out += ' ';
        num(out, st.dashes[i]);
      }
      out += "\"";
      if (st.dash_offset != 0) {
        out += " stroke-dashoffset=\"";
        num(out, st.dash_offset);
        out += "\"";
      }
    }
  }
};

}  // namespace

std::string to_svg(const render::Scene& scene, const Options& o) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
  const int w = scene.width(), h = scene.height();
  // CSS px, 96 to the inch.
  const double css = o.dpi > 0 ? 96.0 / o.dpi : 1.0;
  num(out, w * css);
  out += "\" height=\"";
  num(out, h * css);
  out += "\"";
  out += " viewBox=\"0 0 " + std::to_string(w) + " " + std::to_string(h) + "\">\n";
  if (!o.title.empty()) out += "<title>" + xml_escape(o.title) + "</title>\n";
  const render::Color bg = scene.background();
  if (bg.a > 0) {
    out += "<rect width=\"" + std::to_string(w) + "\" height=\"" + std::to_string(h) + "\" fill=\"" + detail::hex(bg) + "\"";
    if (bg.a < 1) {
      out += " fill-opacity=\"";
      num(out, bg.a);
      out += "\"";
    }
    out += "/>\n";
  }
  SvgWriter sw;
  for (const render::DrawItem& item : detail::unclipped_items(scene)) {
    if (!std::holds_alternative<render::TextItem>(item)) sw.flush();
    std::visit(sw, item);
  }
  sw.flush();
  out += sw.out;
  out += "</svg>\n";
  return out;
}

std::string xml_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const auto u = static_cast<unsigned char>(c);
    // XML 1.0 has no C0 control character but tab, newline and carriage return, and neither
    // U+FFFE nor U+FFFF (EF BF BE, EF BF BF), even as a character reference: each is U+FFFD.
    if (u < 0x20 && c != '\t' && c != '\n' && c != '\r') {
      out += "\xef\xbf\xbd";
      continue;
    }
    if (u == 0xef && i + 2 < s.size() && static_cast<unsigned char>(s[i + 1]) == 0xbf &&
        (static_cast<unsigned char>(s[i + 2]) & 0xfe) == 0xbe) {
      out += "\xef\xbf\xbd";
      i += 2;
      continue;
    }
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace splinefig::vector
