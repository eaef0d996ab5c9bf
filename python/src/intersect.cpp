// SPDX-License-Identifier: MIT
// intersect(a, b=None, *, tolerance=None) and distance(a, b, *, tolerance=None)
// for Python: io::intersection_answer / distance_answer (the answer `hula
// intersect` / `hula distance` print) with the GIL released, as dicts.
#include "hula/nurbs/intersect.hpp"

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

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
  io::Json answer;
  {
    const py::gil_scoped_release release;
    const curve::Curve ca(a);
    const std::optional<curve::Curve> cb = b ? std::optional<curve::Curve>(curve::Curve(*b)) : std::nullopt;
    answer = io::intersection_answer(ca, cb ? &*cb : nullptr, o);
  }
  return to_python(answer);
}

py::object distance(const NurbsCurve& a, const NurbsCurve& b, std::optional<double> tolerance) {
  const nurbs::IntersectOptions o = options_of(tolerance);
  io::Json answer;
  {
    const py::gil_scoped_release release;
    answer = io::distance_answer(curve::Curve(a), curve::Curve(b), o);
  }
  return to_python(answer);
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
