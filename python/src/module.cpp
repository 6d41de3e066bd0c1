// splinefig._core: the C++ half of the Python package (python/splinefig wraps it with argument
// checks, docstrings and type hints).
#include "modules.hpp"

#include <splinefig/image/io.hpp>
#include <splinefig/version.hpp>

#include <stdexcept>

PYBIND11_MODULE(_core, m) {
  namespace py = pybind11;
  m.doc() = "splinefig's C++ library (use the splinefig package, not this module)";
  m.attr("version") = SPLINEFIG_VERSION;
  // Files that cannot be read or written are OSError; every other library error (a bad spec,
  // basis, curve, size or option) is a ValueError with the library's message.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const splinefig::UnreadableImage& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const splinefig::UnwritableImage& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const std::logic_error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  splinefig::python::bind_spline(m);
  splinefig::python::bind_image(m);
  splinefig::python::bind_render(m);
  splinefig::python::bind_resample(m);
  splinefig::python::bind_compare(m);
}
