// SPDX-License-Identifier: MIT
// hulahoops._core: the compiled part of the Python package (docs/python.md).
#include "bindings.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "Compiled core of hulahoops; use the hulahoops package, not this module.";
  hula::python::register_errors(m);
  hula::python::register_geometry(m);
  hula::python::register_laws(m);
  hula::python::register_optimise(m);
  hula::python::register_studies(m);
  hula::python::register_document(m);
  hula::python::register_intersect(m);
  hula::python::register_offset(m);
}
