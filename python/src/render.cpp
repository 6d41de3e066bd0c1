// Rendering: a scene built item by item, or a figure spec, rasterized to linear RGBA.
#include "common.hpp"
#include "modules.hpp"

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/renderer/renderer.hpp>
#include <splinefig/spline/kernel.hpp>

#include <pybind11/stl.h>

#include <array>

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
  throw std::invalid_argument(std::string(what) + ": unknown value '" + name + "' (known: " + names + ")");
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

py::array figure_array(const figures::FigureSpec& spec, double scale, int threads) {
  figures::RenderOptions o;
  o.scale = scale;
  o.threads = threads;
  Image im;
  {
    py::gil_scoped_release unlocked;
    im = figures::render_figure(spec, o).image;
  }
  return array_from_image(std::move(im));
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
        if (w < 1 || h < 1) throw std::invalid_argument("width, height: " + std::to_string(w) + "x" + std::to_string(h) + " is not at least 1x1");
        render::validate_pixel_filter(filter);
        return render::Scene(w, h, color_of(bg), filter);
      }))
      .def_property_readonly("width", &render::Scene::width)
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
      });

  m.def("render_spec_file", [](const std::string& path, double scale, int threads) {
    return spec_errors([&] { return figure_array(figures::load_spec(path), scale, threads); });
  });
  m.def("render_spec_text", [](const std::string& text, const std::string& name, const std::string& base_dir, double scale, int threads) {
    return spec_errors([&] { return figure_array(figures::parse_spec(text, name, base_dir), scale, threads); });
  });
}

}  // namespace splinefig::python
