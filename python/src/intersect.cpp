// SPDX-License-Identifier: MIT
// intersect(a, b=None, *, tolerance=None) and distance(a, b, *, tolerance=None)
// for Python: nurbs::intersect / self_intersect / curve_distance with the GIL
// released, answered as the dicts of io::intersection_to_json /
// curve_distance_to_json (the shape `hula intersect` / `hula distance` print).
#include "hula/nurbs/intersect.hpp"

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "hula/io/intersection_json.hpp"

namespace hula::python {

namespace py = pybind11;
using nurbs::NurbsCurve;

namespace {

nurbs::IntersectOptions options_of(std::optional<double> tolerance) {
  nurbs::IntersectOptions o;
  if (tolerance) o.tolerance.resabs = *tolerance;
  o.validate();
  return o;
}

py::object intersect(const NurbsCurve& a, const std::optional<NurbsCurve>& b, std::optional<double> tolerance) {
  const nurbs::IntersectOptions o = options_of(tolerance);
  nurbs::IntersectionResult r;
  {
    const py::gil_scoped_release release;
    r = b ? nurbs::intersect(a, *b, o) : nurbs::self_intersect(a, o);
  }
  return to_python(io::intersection_to_json(r, std::max(a.dimension(), b ? b->dimension() : 2)));
}

py::object distance(const NurbsCurve& a, const NurbsCurve& b, std::optional<double> tolerance) {
  const nurbs::IntersectOptions o = options_of(tolerance);
  nurbs::CurveDistanceResult r;
  {
    const py::gil_scoped_release release;
    r = nurbs::curve_distance(a, b, o);
  }
  return to_python(io::curve_distance_to_json(r, std::max(a.dimension(), b.dimension())));
}

}  // namespace

void register_intersect(py::module_& m) {
  m.def("intersect", &intersect, py::arg("a"), py::arg("b") = py::none(), py::kw_only(),
        py::arg("tolerance") = py::none(),
        "Where curves a and b meet (b omitted: where a meets itself): {'tolerance', 'points': [{'s', 't', 'point', "
        "'distance', 'angle', 'kind'}], 'overlaps': [{'s', 't', 'start', 'end'}]}.");
  m.def("distance", &distance, py::arg("a"), py::arg("b"), py::kw_only(), py::arg("tolerance") = py::none(),
        "The smallest distance between curves a and b: {'distance', 's', 't', 'point_a', 'point_b'}.");
}

}  // namespace hula::python
