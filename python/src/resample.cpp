// Resampling a numpy image with a kernel: the same call as `splinefig resample`, so the same
// bits. A C-contiguous float32 array is read in place through a view (the argument holds a
// reference to it, so it outlives the call); the GIL is released while the library works (on
// its own threads).
#include "common.hpp"
#include "modules.hpp"

#include <splinefig/resample/resample.hpp>

#include <cstdint>

namespace splinefig::python {

void bind_resample(py::module_& m) {
  m.def("resample", [](const f32array& a, int width, int height, const Kernel& k, const std::string& edge, bool interpolating, int threads) {
    const auto e = parse_edge(edge);
    if (!e) throw ArgumentError("edge: '" + edge + "' is not one of clamp, mirror, wrap, black");
    ResampleOptions o;
    o.edge = *e;
    o.interpolating = interpolating;
    o.threads = threads;
    if (width < 1 || height < 1) throw ArgumentError("resample: the output size is zero");
    const bool squeeze = a.ndim() == 2;
    const int c = a.ndim() == 3 ? static_cast<int>(a.shape(2)) : 1;
    Image out(width, height, c);
    // numpy allows float32 data at any byte address; the library reads floats where they are
    // aligned, so an unaligned array is copied once.
    const bool aligned = reinterpret_cast<std::uintptr_t>(a.data()) % alignof(float) == 0;
    {
      py::gil_scoped_release unlocked;
      if (aligned) {
        const int h = static_cast<int>(a.shape(0)), w = static_cast<int>(a.shape(1));
        resample_into(ImageView{a.data(), w, h, c, std::size_t(w) * std::size_t(c)}, out, k, o);
      } else {
        resample_into(image_from_array(a), out, k, o);
      }
    }
    return array_from_image(std::move(out), squeeze);
  });
}

}  // namespace splinefig::python
