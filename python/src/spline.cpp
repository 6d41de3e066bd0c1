// The spline core: bases, kernels and their analysis, curve evaluation, arc length and
// interpolation. Inputs arrive checked and C-contiguous float64 from the Python layer; outputs
// are written straight into numpy arrays.
#include "common.hpp"
#include "modules.hpp"

#include <splinefig/kernel/analysis.hpp>
#include <splinefig/spline/arclength.hpp>
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/interp.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include <cstring>

namespace splinefig::python {
namespace {

// An (n, d) float64 array as Points (one copy: Points owns its coordinates).
Points points_from(const f64array& a) {
  Points p(static_cast<int>(a.shape(1)), static_cast<std::size_t>(a.shape(0)));
  std::memcpy(p.coords.data(), a.data(), p.coords.size() * sizeof(double));
  return p;
}

py::array_t<double> array_from(Points&& p) {
  const py::ssize_t n = static_cast<py::ssize_t>(p.size()), d = p.dim;
  return array_owning<double>(std::move(p.coords), {n, d});
}

// f(x) for every element of x, into a new array of x's shape, without the GIL.
template <class F>
py::array_t<double> map_array(const f64array& x, F&& f) {
  py::array_t<double> out(std::vector<py::ssize_t>(x.shape(), x.shape() + x.ndim()));
  const double* in = x.data();
  double* o = out.mutable_data();
  const py::ssize_t n = x.size();
  {
    py::gil_scoped_release unlocked;
    for (py::ssize_t i = 0; i < n; ++i) o[i] = f(in[i]);
  }
  return out;
}

py::dict report_dict(const FilterReport& r) {
  py::dict d;
  d["filter"] = r.name;
  d["support"] = py::make_tuple(r.support.lo, r.support.hi);
  d["integral"] = r.integral;
  d["energy"] = r.energy;
  d["continuity"] = r.continuity;
  d["interpolating"] = r.interpolating;
  d["response_at_0"] = r.response_at_0;
  d["response_at_0.25"] = r.response_at_quarter;
  d["response_at_nyquist"] = r.response_at_nyquist;
  d["passband_droop_at_0.25"] = r.droop;
  d["stopband_leakage"] = r.leakage;
  d["step_overshoot"] = r.step.overshoot;
  d["step_undershoot"] = r.step.undershoot;
  d["step_rise_10_90"] = r.step.rise;
  if (r.bc) {
    d["mitchell_netravali"] = py::make_tuple(r.bc->b, r.bc->c);
  } else {
    d["mitchell_netravali"] = py::none();
  }
  d["not_mitchell_netravali"] = r.not_bc;
  d["text"] = report_text(r);
  return d;
}

Curve curve_of(const f64array& knots, const Basis& b, const std::string& ends) {
  return make_curve(b, points_from(knots), parse_ends(ends));
}

}  // namespace

void bind_spline(py::module_& m) {
  py::class_<Basis>(m, "Basis")
      .def_readonly("family", &Basis::family)
      .def_readonly("spec", &Basis::spec)
      .def_readonly("degree", &Basis::degree)
      .def_property_readonly("matrix",
                             [](const Basis& b) {
                               py::array_t<double> a({b.order(), b.order()});
                               std::memcpy(a.mutable_data(), b.m.data(), b.m.size() * sizeof(double));
                               return a;
                             })
      .def_property_readonly("support",
                             [](const Basis& b) {
                               const Support s = kernel_support(b);
                               return py::make_tuple(s.lo, s.hi);
                             })
      .def("__eq__", [](const Basis& a, const Basis& b) { return a.degree == b.degree && a.m == b.m; })
      .def("__repr__", [](const Basis& b) { return "Basis.parse('" + b.spec + "')"; });
  m.def("parse_basis", [](const std::string& s) { return parse_basis(s); });
  m.def("known_bases", &known_bases);
  m.def("catmull_rom", &catmull_rom);
  m.def("cardinal", &cardinal);
  m.def("bspline", &bspline);
  m.def("tensioned_bspline", &tensioned_bspline);
  m.def("beta", &beta);
  m.def("uniform_bspline", &uniform_bspline);
  m.def("mitchell_netravali", &mitchell_netravali_basis);

  py::class_<Kernel>(m, "Kernel")
      .def_property_readonly("name", &Kernel::name)
      .def_property_readonly("support", [](const Kernel& k) { return py::make_tuple(k.support().lo, k.support().hi); })
      .def_property_readonly("polynomial", &Kernel::polynomial)
      .def("integral", &Kernel::integral);
  m.def("basis_kernel", &basis_kernel);
  m.def("parse_kernel", [](const std::string& s) { return parse_kernel(s); });
  m.def("kernel_values", [](const Kernel& k, const f64array& x) { return map_array(x, [&k](double s) { return k(s); }); });
  m.def("kernel_values_into", [](const Kernel& k, const f64array& x, f64array& out) {
    const double* in = x.data();
    double* o = out.mutable_data();
    py::gil_scoped_release unlocked;
    for (py::ssize_t i = 0; i < x.size(); ++i) o[i] = k(in[i]);
  });
  m.def("kernel_derivative", [](const Kernel& k, const f64array& x, int order) {
    if (!k.polynomial()) throw ArgumentError("derivative: " + k.name() + " is not a piecewise polynomial");
    return map_array(x, [&k, order](double s) { return k.derivative(s, order); });
  });
  m.def("response", [](const Kernel& k, const f64array& f) { return map_array(f, [&k](double v) { return response(k, v); }); });
  m.def("fourier", [](const Kernel& k, const f64array& f) {
    py::array_t<std::complex<double>> out(std::vector<py::ssize_t>(f.shape(), f.shape() + f.ndim()));
    const double* in = f.data();
    auto* o = out.mutable_data();
    py::gil_scoped_release unlocked;
    for (py::ssize_t i = 0; i < f.size(); ++i) o[i] = fourier(k, in[i]);
    return out;
  });
  m.def("report", [](const Kernel& k) {
    FilterReport r;
    {
      py::gil_scoped_release unlocked;
      r = analyse(k);
    }
    return report_dict(r);
  });

  m.def("evaluate", [](const f64array& knots, const Basis& b, int grain, const std::string& ends, int derivative) {
    const Curve c = curve_of(knots, b, ends);
    const std::size_t n = sample_count(c, grain);
    py::array_t<double> out({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(c.dim())});
    std::span<double> o(out.mutable_data(), n * static_cast<std::size_t>(c.dim()));
    py::gil_scoped_release unlocked;
    sample_into(c, grain, derivative, o);
    return out;
  });
  m.def("sample_count", [](const f64array& knots, const Basis& b, int grain, const std::string& ends) {
    return sample_count(curve_of(knots, b, ends), grain);
  });
  m.def("evaluate_into", [](const f64array& knots, const Basis& b, int grain, const std::string& ends, int derivative, f64array& out) {
    const Curve c = curve_of(knots, b, ends);
    const std::size_t n = sample_count(c, grain) * static_cast<std::size_t>(c.dim());
    if (static_cast<std::size_t>(out.size()) != n) throw ArgumentError("out: has the wrong size");
    std::span<double> o(out.mutable_data(), n);
    py::gil_scoped_release unlocked;
    sample_into(c, grain, derivative, o);
  });
  m.def("segments", [](const f64array& knots, const Basis& b, const std::string& ends) {
    return curve_of(knots, b, ends).segments();
  });
  m.def("arclength_points", [](const f64array& knots, const Basis& b, std::size_t count, const std::string& ends,
                               const std::string& method, int grain, int derivative) {
    const Curve c = curve_of(knots, b, ends);
    Points p;
    std::vector<double> t;
    {
      py::gil_scoped_release unlocked;
      t = method == "polygon" ? polygon_evenly_spaced_parameters(c, grain, count) : evenly_spaced_parameters(c, count);
      p = evaluate_at(c, t, derivative);
    }
    return py::make_tuple(array_from(std::move(p)), array_owning<double>(std::move(t), {static_cast<py::ssize_t>(count)}));
  });
  m.def("arclength", [](const f64array& knots, const Basis& b, const std::string& ends) {
    const Curve c = curve_of(knots, b, ends);
    py::gil_scoped_release unlocked;
    return arc_length(c).total();
  });

  m.def("interpolate", [](const f64array& data, const std::string& ends, const f64array& v, const f64array& w,
                          const std::string& output, int grain) -> py::object {
    const Points s = points_from(data);
    Interpolant ip;
    if (ends == "relaxed")
      ip = interpolate_relaxed(s);
    else if (ends == "clamped")
      ip = interpolate_clamped(s, {v.data(), static_cast<std::size_t>(v.size())}, {w.data(), static_cast<std::size_t>(w.size())});
    else
      ip = interpolate_periodic(s);
    if (output == "bspline") return array_from(std::move(ip.control));
    if (output == "bezier") {
      BezierSpline b = bezier_pieces(ip);
      const py::ssize_t n = static_cast<py::ssize_t>(b.pieces()), d = b.points.dim;
      py::array_t<double> out({n, py::ssize_t(4), d});
      double* o = out.mutable_data();
      for (py::ssize_t i = 0; i < n; ++i)
        std::memcpy(o + i * 4 * d, b.points.coords.data() + i * 3 * d, static_cast<std::size_t>(4 * d) * sizeof(double));
      return out;
    }
    Points curve;
    {
      py::gil_scoped_release unlocked;
      curve = sample(ip, grain);
    }
    return array_from(std::move(curve));
  });
}

}  // namespace splinefig::python
