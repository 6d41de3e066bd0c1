#pragma once
// What the binding files share: numpy arrays to and from splinefig::Image without extra copies,
// and the release of the GIL around library work.
#include <splinefig/base/error.hpp>
#include <splinefig/image/image.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <string>

namespace splinefig::python {

namespace py = pybind11;

// An argument of a binding's own that the library cannot take (an unknown name, arrays of
// mismatched sizes); a ValueError in Python, as the library's bad_input errors are.
struct ArgumentError : ErrorOf<std::invalid_argument, ErrorKind::bad_input> {
  using ErrorOf::ErrorOf;
};

using f64array = py::array_t<double, py::array::c_style>;
using f32array = py::array_t<float, py::array::c_style>;

// A C-contiguous float32 array of shape (h, w) or (h, w, c) (checked by the Python layer) as an
// Image (one copy: an Image owns its pixels).
Image image_from_array(const f32array& a, Encoding encoding = Encoding::linear);

// The image's pixels as an (h, w, c) float32 array that owns the image (no copy); `squeeze`
// drops the channel axis of a one-channel image.
py::array array_from_image(Image&& im, bool squeeze = false);

// Moves `v` to the heap and returns a numpy array of `shape` viewing it (no copy).
template <class T, class Vec>
py::array_t<T> array_owning(Vec&& v, std::vector<py::ssize_t> shape) {
  auto* owned = new Vec(std::move(v));
  py::capsule free_it(owned, [](void* p) { delete static_cast<Vec*>(p); });
  return py::array_t<T>(shape, owned->data(), free_it);
}

}  // namespace splinefig::python
