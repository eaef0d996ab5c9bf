// SPDX-License-Identifier: MIT
// The registration functions of the hulahoops._core extension module, one per
// source file: errors.cpp (hula::Error -> hulahoops.Error subclasses),
// geometry.cpp (NurbsCurve, interpolate, analyse, reconstruct), laws.cpp
// (Law), optimise.cpp (Flexo with Python objectives), studies.cpp (the
// thesis's curve studies), document.cpp (the Oli document) and exchange.cpp (read/write curve files). The Python
// package (python/hulahoops) wraps these in its documented public API.
#pragma once

#include <pybind11/pybind11.h>

namespace hula::python {

void register_errors(pybind11::module_& m);
void register_geometry(pybind11::module_& m);
void register_laws(pybind11::module_& m);
void register_optimise(pybind11::module_& m);
void register_studies(pybind11::module_& m);
void register_document(pybind11::module_& m);
void register_intersect(pybind11::module_& m);
void register_offset(pybind11::module_& m);
void register_exchange(pybind11::module_& m);

}  // namespace hula::python
