// Rendering: a scene built item by item, or a figure spec, rasterized to linear RGBA.
#include "common.hpp"
#include "modules.hpp"

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/output.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/image/srgb.hpp>
#include <splinefig/renderer/path.hpp>
#include <splinefig/renderer/renderer.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>

namespace splinefig::python {
namespace {

using render::Color;
using render::Vec2;

Color color_of(const std::array<float, 4>& c) { return {c[0], c[1], c[2], c[3]}; }

std::vector<Vec2> vec2s(const f64array& a) {
  std::vector<Vec2> v(static_cast<std::size_t>(a.shape(0)));
  const double* p = a.data();
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = {p[2 * i], p[2 * i + 1]};
  return v;
}

template <class E>
E pick(const std::string& name, const char* what, std::initializer_list<std::pair<const char*, E>> known) {
  std::string names;
  for (const auto& [n, e] : known) {
    if (name == n) return e;
    names += (names.empty() ? "" : ", ") + std::string(n);
  }
  throw ArgumentError(std::string(what) + ": unknown value '" + name + "' (known: " + names + ")");
}

render::StrokeStyle stroke_of(double width, const std::string& join, const std::string& cap, double miter_limit,
                              std::vector<double> dashes, double dash_offset) {
  render::StrokeStyle s;
  s.width = width;
  s.join = pick<render::Join>(join, "join", {{"miter", render::Join::Miter}, {"round", render::Join::Round}, {"bevel", render::Join::Bevel}});
  s.cap = pick<render::Cap>(cap, "cap", {{"butt", render::Cap::Butt}, {"round", render::Cap::Round}, {"square", render::Cap::Square}});
  s.miter_limit = miter_limit;
  s.dashes = render::DashPattern(std::move(dashes));
  s.dash_offset = dash_offset;
  return s;
}

using u8array = py::array_t<std::uint8_t, py::array::c_style>;

// A matplotlib-style path: (n, 2) vertices and n codes (0 stop, 1 move, 2 line, 3 quadratic
// Bezier: this vertex is the control point, the next the end, 4 cubic: this and the next are
// the controls, the third the end, 79 close; an empty code array: a polyline). A curve that
// runs past the end or lacks a start point throws, naming the vertex.
// With an offset (dx, dy) added to every vertex, then an origin (ox, oy) taken off: the same
// doubles as adding and subtracting them in numpy.
render::Path path_of(const f64array& vertices, const u8array& codes, double dx = 0, double dy = 0, double ox = 0, double oy = 0) {
  const std::size_t n = static_cast<std::size_t>(vertices.shape(0));
  const double* v = vertices.data();
  const std::uint8_t* c = codes.size() ? codes.data() : nullptr;
  if (c && static_cast<std::size_t>(codes.size()) != n)
    throw ArgumentError("codes: " + std::to_string(codes.size()) + " codes for " + std::to_string(n) + " vertices");
  render::Path path;
  bool started = false;
  const bool moved = dx != 0 || dy != 0 || ox != 0 || oy != 0;
  auto at = [&](std::size_t i) {
    if (!moved) return Vec2{v[2 * i], v[2 * i + 1]};
    return Vec2{(v[2 * i] + dx) - ox, (v[2 * i + 1] + dy) - oy};
  };
  for (std::size_t i = 0; i < n;) {
    const int code = c ? c[i] : (i == 0 ? 1 : 2);
    if (code == 0) break;
    if (code == 79) {
      if (started) path.close();
      ++i;
      continue;
    }
    if (code == 1 || (!started && code == 2)) {
      path.move_to(at(i));
      started = true;
      ++i;
      continue;
    }
    const std::size_t need = code == 2 ? 1 : code == 3 ? 2 : code == 4 ? 3 : 0;
    if (need == 0) throw ArgumentError("codes: unknown path code " + std::to_string(code) + " at vertex " + std::to_string(i));
    if (!started) throw ArgumentError("codes: a curve with no start point at vertex " + std::to_string(i));
    if (i + need > n) throw ArgumentError("codes: the curve at vertex " + std::to_string(i) + " runs past the last vertex");
    if (code == 2) path.line_to(at(i));
    else if (code == 3) path.quad_to(at(i), at(i + 1));
    else path.cubic_to(at(i), at(i + 1), at(i + 2));
    i += need;
  }
  return path;
}

// An (h, w, 4) RGBA array as the linear, associated-alpha image Scene::image takes: uint8 codes
// are sRGB with straight alpha (as matplotlib's images), decoded by the library's table; float32
// is taken as given (already linear and associated).
std::shared_ptr<Image> rgba_image(const py::array& a) {
  const int h = static_cast<int>(a.shape(0)), w = static_cast<int>(a.shape(1));
  if (py::isinstance<py::array_t<std::uint8_t>>(a)) {
    const auto u = u8array::ensure(a);
    auto im = std::make_shared<Image>(w, h, 4);
    const std::uint8_t* s = u.data();
    float* d = im->pixels.data();
    const std::size_t count = static_cast<std::size_t>(w) * h;
    for (std::size_t i = 0; i < count; ++i, s += 4, d += 4) {
      const float alpha = s[3] / 255.0f;
      for (int ch = 0; ch < 3; ++ch) d[ch] = srgb8_to_linear(s[ch]) * alpha;
      d[3] = alpha;
    }
    return im;
  }
  return std::make_shared<Image>(image_from_array(f32array::ensure(a)));
}

// The rasterized canvas (associated alpha, linear or sRGB-encoded) as 8-bit sRGB with straight
// alpha, rows top to bottom: what PNG files and matplotlib's buffers hold. A pixel of alpha 0
// becomes `clear` (r, g, b, 0).
py::array rgba8_of(const Image& im, std::array<std::uint8_t, 3> clear) {
  const std::size_t count = im.pixel_count();
  std::vector<std::uint8_t> out(count * 4);
  const float* s = im.pixels.data();
  const bool srgb = im.encoding == Encoding::srgb;
  // lround of a value in [0, 255] (0 for NaN), without the library call: a float plus 0.5 is
  // exact in double.
  const auto round8 = [](float v) { return v > 0.0f ? static_cast<std::uint8_t>(static_cast<double>(v) + 0.5) : std::uint8_t{0}; };
  {
    py::gil_scoped_release unlocked;
    for (std::size_t i = 0; i < count; ++i, s += 4) {
      std::uint8_t* d = &out[4 * i];
      const float a = std::clamp(s[3], 0.0f, 1.0f);
      const std::uint8_t a8 = round8(a * 255.0f);
      if (a8 == 0) {
        d[0] = clear[0], d[1] = clear[1], d[2] = clear[2], d[3] = 0;
        continue;
      }
      for (int ch = 0; ch < 3; ++ch) {
        const float v = a == 1.0f ? s[ch] : s[ch] / a;  // most pixels are opaque: skip the division
        d[ch] = srgb ? round8(std::clamp(v, 0.0f, 1.0f) * 255.0f) : linear_to_srgb8(v);
      }
      d[3] = a8;
    }
  }
  return array_owning<std::uint8_t>(std::move(out), {im.height, im.width, 4});
}

// A RasterReport as {"tolerance", "band_rows", "items": [{"index", "bands", "piece_bands"}]}.
py::dict report_dict(const render::RasterReport& r) {
  py::list items;
  for (const render::RasterReport::Item& it : r.items) {
    py::dict d;
    d["index"] = it.index;
    d["bands"] = it.bands;
    d["piece_bands"] = it.piece_bands;
    items.append(d);
  }
  py::dict d;
  d["tolerance"] = r.tolerance;
  d["band_rows"] = r.band_rows;
  d["items"] = items;
  return d;
}

py::array figure_array(const figures::FigureSpec& spec, double scale, int threads) {
  figures::RenderOptions o;
  o.scale = scale;
  o.threads = threads;
  Image im;
  {
    py::gil_scoped_release unlocked;
    // In linear light whatever the blend space: the decode of what was composited (sRGB by
    // default), the values the figure's EXR holds.
    im = to_linear(figures::render_figure(spec, o).image);
  }
  return array_from_image(std::move(im));
}

// The figure as `splinefig render -o FIG.svg --scale SCALE` writes it.
std::string figure_svg_text(const figures::FigureSpec& spec, double scale) {
  figures::check_scaled_canvas(spec, scale, "scale");
  figures::FigureFileOptions o;
  o.scale = scale;
  o.dpi = spec.canvas.print_dpi();  // the printed size, as render without --dpi
  o.title = figures::file_title(spec);
  py::gil_scoped_release unlocked;
  return figures::figure_svg(figures::figure_scene(spec, scale), o);
}

template <class F>
auto spec_errors(F&& f) {
  try {
    return f();
  } catch (const figures::SpecFileError& e) {
    throw py::value_error(e.what());
  }
}

}  // namespace

void bind_render(py::module_& m) {
  m.def("parse_hex_color", [](const std::string& s) -> std::optional<std::array<float, 4>> {
    const auto c = render::parse_hex_color(s);
    if (!c) return std::nullopt;
    return std::array<float, 4>{c->r, c->g, c->b, c->a};
  });
  py::class_<render::Scene>(m, "Scene")
      .def(py::init([](int w, int h, const std::array<float, 4>& bg, const Kernel& filter) {
        if (w < 1 || h < 1) throw ArgumentError("width, height: " + std::to_string(w) + "x" + std::to_string(h) + " is not at least 1x1");
        render::validate_pixel_filter(filter);
        return render::Scene(w, h, color_of(bg), filter);
      }))
      .def_property_readonly("width", &render::Scene::width)
      .def_property("blend", [](const render::Scene& s) { return std::string(s.blend_space() == render::BlendSpace::srgb ? "srgb" : "linear"); },
                    [](render::Scene& s, const std::string& b) {
                      s.set_blend_space(pick<render::BlendSpace>(b, "blend", {{"linear", render::BlendSpace::linear}, {"srgb", render::BlendSpace::srgb}}));
                    })
      .def_property("coverage_tolerance", &render::Scene::coverage_tolerance, &render::Scene::set_coverage_tolerance)
      .def("fill_path", [](render::Scene& s, const f64array& vertices, const u8array& codes, const std::string& rule, const std::array<float, 4>& color) {
        s.fill_path(path_of(vertices, codes),
                    pick<render::FillRule>(rule, "rule", {{"nonzero", render::FillRule::NonZero}, {"evenodd", render::FillRule::EvenOdd}}),
                    color_of(color));
      })
      .def("set_clip", [](render::Scene& s, const f64array& vertices, const u8array& codes, const std::string& rule) {
        s.set_clip(path_of(vertices, codes),
                   pick<render::FillRule>(rule, "rule", {{"nonzero", render::FillRule::NonZero}, {"evenodd", render::FillRule::EvenOdd}}));
      })
      .def("clear_clip", &render::Scene::clear_clip)
      .def("stroke_path", [](render::Scene& s, const f64array& vertices, const u8array& codes, const std::array<float, 4>& color, double width,
                             const std::string& join, const std::string& cap, double miter_limit, std::vector<double> dashes, double dash_offset) {
        s.stroke_path(path_of(vertices, codes), stroke_of(width, join, cap, miter_limit, std::move(dashes), dash_offset), color_of(color));
      })
      // One path drawn at n offsets, each its own items in order: its fill (fills[i], skipped
      // where the alpha is negative), then its stroke (strokes[i] at widths[i], skipped where
      // the width is not positive or the alpha negative), with one join, cap and dash pattern.
      // Item i's vertices are (vertex + offsets[i]) - origin. A matplotlib path collection.
      .def("path_items", [](render::Scene& s, const f64array& vertices, const u8array& codes, const f64array& offsets,
                            const f64array& fills, const f64array& strokes, const f64array& widths, const std::string& rule,
                            const std::string& join, const std::string& cap, double miter_limit, std::vector<double> dashes,
                            double dash_offset, double ox, double oy) {
        const py::ssize_t n = offsets.ndim() == 2 && offsets.shape(1) == 2 ? offsets.shape(0) : -1;
        if (n < 0) throw py::value_error("offsets: expected an (n, 2) array");
        if (fills.ndim() != 2 || fills.shape(0) != n || fills.shape(1) != 4) throw py::value_error("fills: expected an (n, 4) array");
        if (strokes.ndim() != 2 || strokes.shape(0) != n || strokes.shape(1) != 4) throw py::value_error("strokes: expected an (n, 4) array");
        if (widths.ndim() != 1 || widths.shape(0) != n) throw py::value_error("widths: expected n widths");
        const auto fill_rule = pick<render::FillRule>(rule, "rule", {{"nonzero", render::FillRule::NonZero}, {"evenodd", render::FillRule::EvenOdd}});
        const double* o = offsets.data();
        const double* f = fills.data();
        const double* k = strokes.data();
        const double* w = widths.data();
        const auto color = [](const double* c) {
          return render::Color{static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]), static_cast<float>(c[3])};
        };
        for (py::ssize_t i = 0; i < n; ++i, o += 2, f += 4, k += 4) {
          const bool fill = f[3] >= 0, stroke = w[i] > 0 && k[3] >= 0;
          if (!fill && !stroke) continue;
          const render::Path path = path_of(vertices, codes, o[0], o[1], ox, oy);
          if (fill) s.fill_path(path, fill_rule, color(f));
          if (stroke) s.stroke_path(path, stroke_of(w[i], join, cap, miter_limit, dashes, dash_offset), color(k));
        }
      })
      .def("image", [](render::Scene& s, const py::array& rgba, double x0, double y0, double x1, double y1, const std::string& sampling) {
        const auto smp = pick<render::Scene::Sampling>(sampling, "sampling", {{"nearest", render::Scene::Sampling::Nearest},
                                                                              {"bilinear", render::Scene::Sampling::Bilinear}});
        s.image(rgba_image(rgba), {x0, y0}, {x1, y1}, smp);
      })
      // One picture placed at many places, each its own item at its own size (nearest
      // sampling): its pixels are held once, however many times it is drawn. A float picture is
      // linear light, or with encoding "srgb" sRGB-encoded values (what a Scene blending in sRGB
      // renders), composited without a round trip through linear light.
      .def("images", [](render::Scene& s, const py::array& rgba, const f64array& origins, const std::string& encoding) {
        if (origins.ndim() != 2 || origins.shape(1) != 2) throw py::value_error("origins: expected an (n, 2) array");
        const Encoding enc = pick<Encoding>(encoding, "encoding", {{"linear", Encoding::linear}, {"srgb", Encoding::srgb}});
        if (enc == Encoding::srgb && !py::isinstance<py::array_t<float>>(rgba))
          throw py::value_error("encoding: \"srgb\" is for a float32 picture (uint8 is sRGB already)");
        const auto im = rgba_image(rgba);
        im->encoding = enc;
        const double w = im->width, h = im->height;
        const double* o = origins.data();
        for (py::ssize_t i = 0; i < origins.shape(0); ++i, o += 2)
          s.image(im, {o[0], o[1]}, {o[0] + w, o[1] + h}, render::Scene::Sampling::Nearest);
      }, py::arg("rgba"), py::arg("origins"), py::arg("encoding") = "linear")
      // The same, composited first into one picture over the places' bounding box, which goes
      // into the scene as one item: each copy over the ones before it (associated alpha, the
      // scene's over: p + d (1 - alpha), in the picture's values), which over is associative
      // with, so the canvas gets what the copies one by one would give it (to float rounding).
      // The places are whole pixels; the copies of a marker all over a plot cost one item
      // instead of one each. The box is bounded by the places, which the caller keeps on the
      // canvas.
      .def("stamps", [](render::Scene& s, const f32array& rgba, const f64array& origins, const std::string& encoding) {
        if (origins.ndim() != 2 || origins.shape(1) != 2) throw py::value_error("origins: expected an (n, 2) array");
        if (rgba.ndim() != 3 || rgba.shape(2) != 4) throw py::value_error("rgba: expected an (h, w, 4) float32 array");
        const Encoding enc = pick<Encoding>(encoding, "encoding", {{"linear", Encoding::linear}, {"srgb", Encoding::srgb}});
        const py::ssize_t n = origins.shape(0);
        if (n == 0) return;
        // Only the picture's pixels that hold something (a marker's picture has a margin of
        // nothing around it): over leaves the canvas as it is under a pixel of 0.
        const int pw = static_cast<int>(rgba.shape(1)), ph = static_cast<int>(rgba.shape(0));
        int cx0 = pw, cy0 = ph, cx1 = 0, cy1 = 0;
        for (int y = 0; y < ph; ++y)
          for (int x = 0; x < pw; ++x) {
            const float* p = rgba.data() + 4 * (static_cast<std::size_t>(y) * pw + x);
            if (p[0] != 0 || p[1] != 0 || p[2] != 0 || p[3] != 0)
              cx0 = std::min(cx0, x), cy0 = std::min(cy0, y), cx1 = std::max(cx1, x + 1), cy1 = std::max(cy1, y + 1);
          }
        const double* o = origins.data();
        double x0 = o[0], y0 = o[1], x1 = o[0], y1 = o[1];
        for (py::ssize_t i = 0; i < n; ++i) {
          const double x = o[2 * i], y = o[2 * i + 1];
          if (!(x == std::floor(x) && y == std::floor(y) && std::abs(x) < 1e9 && std::abs(y) < 1e9))
            throw py::value_error("origins: place " + std::to_string(i) + " is not a whole pixel on the canvas");
          x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
        }
        if (cx1 <= cx0) return;
        const int w = cx1 - cx0, h = cy1 - cy0;
        const double bw = x1 - x0 + w, bh = y1 - y0 + h;
        if (bw * bh > 4.0 * (double(s.width()) + w) * (double(s.height()) + h))
          throw py::value_error("origins: the places span " + std::to_string(bw) + " x " + std::to_string(bh) + " px, past the canvas");
        auto layer = std::make_shared<Image>(Image::zeros(static_cast<int>(bw), static_cast<int>(bh), 4, enc));
        const float* src = rgba.data();
        {
          py::gil_scoped_release unlocked;
          for (py::ssize_t i = 0; i < n; ++i) {
            const int ox = static_cast<int>(o[2 * i] - x0), oy = static_cast<int>(o[2 * i + 1] - y0);
            for (int y = 0; y < h; ++y) {
              const float* p = src + 4 * (static_cast<std::size_t>(y + cy0) * pw + cx0);
              float* d = layer->pixel(ox, oy + y);
              for (int x = 0; x < w; ++x, p += 4, d += 4) {
                const float k = 1.0f - p[3];
                for (int ch = 0; ch < 4; ++ch) d[ch] = p[ch] + d[ch] * k;
              }
            }
          }
        }
        s.image(layer, {x0 + cx0, y0 + cy0}, {x0 + cx0 + bw, y0 + cy0 + bh}, render::Scene::Sampling::Nearest);
      }, py::arg("rgba"), py::arg("origins"), py::arg("encoding") = "linear")
      .def_property_readonly("height", &render::Scene::height)
      .def("polyline", [](render::Scene& s, const f64array& pts, bool closed, const std::array<float, 4>& color, double width,
                          const std::string& join, const std::string& cap, double miter_limit, std::vector<double> dashes,
                          double dash_offset) {
        s.stroke_polyline(vec2s(pts), closed, stroke_of(width, join, cap, miter_limit, std::move(dashes), dash_offset), color_of(color));
      })
      .def("fill", [](render::Scene& s, const std::vector<f64array>& contours, const std::string& rule, const std::array<float, 4>& color) {
        std::vector<std::vector<Vec2>> cs;
        for (const auto& c : contours) cs.push_back(vec2s(c));
        s.fill_polygon(cs, pick<render::FillRule>(rule, "rule", {{"nonzero", render::FillRule::NonZero}, {"evenodd", render::FillRule::EvenOdd}}),
                       color_of(color));
      })
      .def("fill_circle", [](render::Scene& s, double x, double y, double r, const std::array<float, 4>& color) {
        s.fill_circle({x, y}, r, color_of(color));
      })
      .def("stroke_circle", [](render::Scene& s, double x, double y, double r, const std::array<float, 4>& color, double width) {
        s.stroke_circle({x, y}, r, stroke_of(width, "miter", "butt", 4, {}, 0), color_of(color));
      })
      .def("markers", [](render::Scene& s, const f64array& pts, const std::string& shape, double size, const std::array<float, 4>& color) {
        const auto shp = pick<render::Marker>(shape, "shape", {{"circle", render::Marker::Circle}, {"square", render::Marker::Square},
                                                               {"diamond", render::Marker::Diamond}, {"cross", render::Marker::Cross},
                                                               {"plus", render::Marker::Plus}});
        for (const Vec2& p : vec2s(pts)) s.marker(shp, p, size, color_of(color));
      })
      .def("text", [](render::Scene& s, const std::string& text, double x, double y, double size, const std::array<float, 4>& color,
                      const std::string& halign, const std::string& valign, const std::string& family, const std::string& weight,
                      bool italic, double angle) {
        render::TextStyle t;
        t.size = size;
        t.color = color_of(color);
        t.halign = pick<render::HAlign>(halign, "halign", {{"left", render::HAlign::Left}, {"center", render::HAlign::Center}, {"right", render::HAlign::Right}});
        t.valign = pick<render::VAlign>(valign, "valign", {{"baseline", render::VAlign::Baseline}, {"middle", render::VAlign::Middle},
                                                           {"top", render::VAlign::Top}, {"bottom", render::VAlign::Bottom}});
        t.family = pick<render::FontFamily>(family, "family", {{"sans", render::FontFamily::Sans}, {"serif", render::FontFamily::Serif},
                                                               {"mono", render::FontFamily::Mono}});
        t.weight = pick<render::FontWeight>(weight, "weight", {{"normal", render::FontWeight::Normal}, {"bold", render::FontWeight::Bold}});
        t.italic = italic;
        t.angle = angle;
        s.text(text, {x, y}, t);
      })
      .def("render", [](const render::Scene& s, int threads) {
        Image im;
        {
          py::gil_scoped_release unlocked;
          im = render::rasterize(s, threads);
        }
        return array_from_image(std::move(im));
      })
      .def("render_rgba8", [](const render::Scene& s, int threads, const std::array<std::uint8_t, 3>& clear) {
        Image im;
        {
          py::gil_scoped_release unlocked;
          im = render::rasterize(s, threads);
        }
        return rgba8_of(im, clear);
      })
      // The same two, with how the picture was rasterized (render::RasterReport) as a dict.
      .def("render_reported", [](const render::Scene& s, int threads) {
        Image im;
        render::RasterReport r;
        {
          py::gil_scoped_release unlocked;
          im = render::rasterize(s, threads, &r);
        }
        return py::make_tuple(array_from_image(std::move(im)), report_dict(r));
      })
      .def("render_rgba8_reported", [](const render::Scene& s, int threads, const std::array<std::uint8_t, 3>& clear) {
        Image im;
        render::RasterReport r;
        {
          py::gil_scoped_release unlocked;
          im = render::rasterize(s, threads, &r);
        }
        return py::make_tuple(rgba8_of(im, clear), report_dict(r));
      });
  // An sRGB-encoded associated-alpha RGBA array (what rasterize gives in sRGB blend space) as
  // linear light, associated (what Scene::image takes), by the library's curve.
  m.def("srgb_to_linear_rgba", [](const f32array& a) {
    Image im = image_from_array(a, Encoding::srgb);
    {
      py::gil_scoped_release unlocked;
      im = to_linear(im);
    }
    return array_from_image(std::move(im));
  });

  m.def("render_spec_file", [](const std::string& path, double scale, int threads) {
    return spec_errors([&] { return figure_array(figures::load_spec(path), scale, threads); });
  });
  m.def("render_spec_text", [](const std::string& text, const std::string& name, const std::string& base_dir, double scale, int threads) {
    return spec_errors([&] { return figure_array(figures::parse_spec(text, name, base_dir), scale, threads); });
  });
  m.def("spec_svg_file", [](const std::string& path, double scale) {
    return spec_errors([&] { return figure_svg_text(figures::load_spec(path), scale); });
  });
  m.def("spec_svg_text", [](const std::string& text, const std::string& name, const std::string& base_dir, double scale) {
    return spec_errors([&] { return figure_svg_text(figures::parse_spec(text, name, base_dir), scale); });
  });
}

}  // namespace splinefig::python
