// SPDX-License-Identifier: MIT
// hulahoops._core: the compiled part of the Python package (docs/python.md).
#include "bindings.hpp"
#include "hula/version.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "Compiled core of hulahoops; use the hulahoops package, not this module.";
  // The project's version (CMake's project(VERSION)), the one pyproject's metadata carries too.
  m.attr("__version__") = hula::kVersionString;
  hula::python::register_errors(m);
  hula::python::register_geometry(m);
  hula::python::register_laws(m);
  hula::python::register_optimise(m);
  hula::python::register_studies(m);
  hula::python::register_document(m);
  hula::python::register_intersect(m);
  hula::python::register_offset(m);
  hula::python::register_exchange(m);
}
