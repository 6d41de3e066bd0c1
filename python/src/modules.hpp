#pragma once
// One registration function per binding file; module.cpp calls them all.
#include <pybind11/pybind11.h>

namespace splinefig::python {

void bind_spline(pybind11::module_& m);
void bind_image(pybind11::module_& m);
void bind_render(pybind11::module_& m);
void bind_resample(pybind11::module_& m);
void bind_compare(pybind11::module_& m);

}  // namespace splinefig::python
