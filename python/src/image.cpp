// Images: numpy arrays <-> splinefig::Image, files through the library's strict reader and
// atomic writer.
#include "common.hpp"
#include "modules.hpp"

#include <splinefig/base/huge_pages.hpp>
#include <splinefig/image/io.hpp>

#include <cstdint>
#include <cstring>

namespace splinefig::python {

Image image_from_array(const f32array& a, Encoding encoding) {
  const int h = static_cast<int>(a.shape(0)), w = static_cast<int>(a.shape(1));
  const int c = a.ndim() == 3 ? static_cast<int>(a.shape(2)) : 1;
  Image im(w, h, c, encoding);
  // Huge pages before the first write: 512 times fewer page faults in the copy below.
  advise_huge_pages(im.pixels.data(), im.pixels.size() * sizeof(float));
  std::memcpy(im.pixels.data(), a.data(), im.pixels.size() * sizeof(float));
  return im;
}

constexpr const char* kImageCapsule = "splinefig.Image";

py::array array_from_image(Image&& im, bool squeeze) {
  std::vector<py::ssize_t> shape{im.height, im.width};
  if (!(squeeze && im.channels == 1)) shape.push_back(im.channels);
  auto* owned = new Image(std::move(im));
  py::capsule free_it(owned, kImageCapsule, [](PyObject* c) { delete static_cast<Image*>(PyCapsule_GetPointer(c, kImageCapsule)); });
  return py::array_t<float>(shape, owned->pixels.data(), free_it);
}

void bind_image(py::module_& m) {
  m.def("image_buffer", [](int height, int width, int channels, bool squeeze) {
    return array_from_image(Image::zeros(width, height, channels), squeeze);
  });
  m.def(
      "read_image",
      [](const std::string& path, bool linear) {
        Image im;
        {
          py::gil_scoped_release unlocked;
          im = read_image(path, linear ? ReadMode::linear : ReadMode::as_stored);
        }
        const bool srgb = im.encoding == Encoding::srgb;
        return py::make_tuple(array_from_image(std::move(im)), srgb ? "srgb" : "linear");
      },
      py::arg("path"), py::arg("linear"));
  m.def(
      "write_image",
      [](const std::string& path, const f32array& a, bool srgb, int bits, const std::string& description) {
        const Image im = image_from_array(a, srgb ? Encoding::srgb : Encoding::linear);
        WriteOptions o;
        o.bits = bits;
        o.description = description;
        py::gil_scoped_release unlocked;
        write_image(path, im, o);
      },
      py::arg("path"), py::arg("array"), py::arg("srgb"), py::arg("bits"), py::arg("description"));
}

}  // namespace splinefig::python
