// splinefig._core: the C++ half of the Python package (python/splinefig wraps it with argument
// checks, docstrings and type hints).
#include "modules.hpp"

#include <splinefig/base/error.hpp>
#include <splinefig/version.hpp>

#include <stdexcept>

PYBIND11_MODULE(_core, m) {
  namespace py = pybind11;
  m.doc() = "splinefig's C++ library (use the splinefig package, not this module)";
  m.attr("version") = SPLINEFIG_VERSION;
  // By the error's kind (base/error.hpp): files that cannot be read or written are OSError;
  // every other library error (a bad spec, basis, curve, size or option) that is a
  // std::logic_error (std::invalid_argument, ...) is a ValueError with the library's message;
  // the rest are pybind11's (std::runtime_error is RuntimeError).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const std::exception& e) {
      const splinefig::ErrorKind kind = splinefig::error_kind(e);
      if (kind == splinefig::ErrorKind::unreadable || kind == splinefig::ErrorKind::unwritable)
        PyErr_SetString(PyExc_OSError, e.what());
      else if (dynamic_cast<const std::logic_error*>(&e))
        PyErr_SetString(PyExc_ValueError, e.what());
      else
        throw;
    }
  });
  splinefig::python::bind_spline(m);
  splinefig::python::bind_image(m);
  splinefig::python::bind_render(m);
  splinefig::python::bind_resample(m);
  splinefig::python::bind_compare(m);
}
