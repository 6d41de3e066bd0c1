// Resampling a numpy image with a kernel: the same call as `splinefig resample`, so the same
// bits. The GIL is released while the library works (on its own threads).
#include "common.hpp"
#include "modules.hpp"

#include <splinefig/resample/resample.hpp>

namespace splinefig::python {

void bind_resample(py::module_& m) {
  m.def("resample", [](const f32array& a, int width, int height, const Kernel& k, const std::string& edge, bool interpolating, int threads) {
    const auto e = parse_edge(edge);
    if (!e) throw std::invalid_argument("edge: '" + edge + "' is not one of clamp, mirror, wrap, black");
    ResampleOptions o;
    o.edge = *e;
    o.interpolating = interpolating;
    o.threads = threads;
    const bool squeeze = a.ndim() == 2;
    Image out;
    const Image* in_place = borrowed_image(a);
    {
      py::gil_scoped_release unlocked;
      if (in_place) {
        out = resample(*in_place, width, height, k, o);
      } else {
        const Image src = image_from_array(a);
        out = resample(src, width, height, k, o);
      }
    }
    return array_from_image(std::move(out), squeeze);
  });
}

}  // namespace splinefig::python
