// SPDX-License-Identifier: MIT
// offset(curve, distance, *, tolerance=None, trim=True) and
// helical_offset(curve, distance, *, twist="0", frame="frenet", tolerance=None)
// orthotomic(curve, pole, *, k=2) and polar_map(curve, centre, *, radius=1)
// for Python: io::offset_answer, helical_offset_answer, orthotomic_answer and
// polar_answer (what the `hula` commands print) with the GIL released, as
// dicts. The curve is a NurbsCurve, a curve file as a dict, or its path.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "hula/core/error.hpp"
#include "hula/io/frenet_handles_json.hpp"
#include "hula/io/offset_json.hpp"

namespace hula::python {

namespace py = pybind11;

namespace {

py::object offset(const py::object& curve, double distance, std::optional<double> tolerance, bool trim) {
  const curve::Curve c = curve_value(curve);
  diffgeom::OffsetOptions o;
  if (tolerance) o.tolerance = *tolerance;
  o.trim = trim;
  io::Json answer;
  {
    const py::gil_scoped_release release;
    answer = io::offset_answer(c, distance, o);
  }
  return to_python(answer);
}

py::object helical_offset(const py::object& curve, const std::string& distance, const std::string& twist,
                          const std::string& frame, std::optional<double> tolerance) {
  const curve::Curve c = curve_value(curve);
  diffgeom::HelicalOffsetOptions o;
  const std::optional<diffgeom::OffsetFrame> f = diffgeom::offset_frame_from_name(frame);
  if (!f)
    throw Error(Errc::InvalidOption, "frame must be 'frenet' or 'bishop', got '" + frame + "'", {.field = "frame"});
  o.frame = *f;
  if (tolerance) o.tolerance = *tolerance;
  io::Json answer;
  {
    const py::gil_scoped_release release;
    answer = io::helical_offset_answer(c, distance, twist, o);
  }
  return to_python(answer);
}

Vec3 point_of(const std::vector<double>& v, const char* field) {
  if (v.size() != 2 && v.size() != 3)
    throw Error(Errc::InvalidArgument,
                std::string(field) + " needs 2 or 3 coordinates, got " + std::to_string(v.size()), {.field = field});
  return {v[0], v[1], v.size() == 3 ? v[2] : 0.0};
}

diffgeom::MappingOptions mapping_options(std::optional<double> tolerance) {
  diffgeom::MappingOptions o;
  if (tolerance) o.tolerance = *tolerance;
  return o;
}

py::object orthotomic(const py::object& curve, const std::vector<double>& pole, double k,
                      std::optional<double> tolerance) {
  const curve::Curve c = curve_value(curve);
  const Vec3 p = point_of(pole, "pole");
  io::Json answer;
  {
    const py::gil_scoped_release release;
    answer = io::orthotomic_answer(c, p, k, mapping_options(tolerance));
  }
  return to_python(answer);
}

py::object polar_map(const py::object& curve, const std::vector<double>& centre, double radius,
                     std::optional<double> tolerance) {
  const curve::Curve c = curve_value(curve);
  const Vec3 p = point_of(centre, "centre");
  io::Json answer;
  {
    const py::gil_scoped_release release;
    answer = io::polar_answer(c, p, radius, mapping_options(tolerance));
  }
  return to_python(answer);
}

nurbs::NurbsCurve hermite_frenet(const py::object& document) {
  const io::Json doc = from_python(document, "handles");
  const py::gil_scoped_release release;
  return io::hermite_frenet_curve(doc);
}

}  // namespace

void register_offset(py::module_& m) {
  m.def("offset", &offset, py::arg("curve"), py::arg("distance"), py::kw_only(), py::arg("tolerance") = py::none(),
        py::arg("trim") = true,
        "Planar offset of a plane curve by distance (positive to the left): {'distance', 'tolerance', 'exact', "
        "'deviation', 'raw' (curve file), 'cusps', 'loops': [{'s', 't', 'point', 'angle'}], 'trimmed': [{'spans', "
        "'closed', 'curve'}]}.");
  m.def("helical_offset", &helical_offset, py::arg("curve"), py::arg("distance"), py::kw_only(), py::arg("twist") = "0",
        py::arg("frame") = "frenet", py::arg("tolerance") = py::none(),
        "Helical offset C + d (cos θ U + sin θ V) in the Frenet or Bishop frame, d and θ law texts of the curve "
        "parameter: {'frame', 'distance', 'twist', 'tolerance', 'exact', 'deviation', 'plane_normal'?, 'curve'}.");
  m.def("orthotomic", &orthotomic, py::arg("curve"), py::arg("pole"), py::kw_only(), py::arg("k") = 2.0,
        py::arg("tolerance") = py::none(),
        "K-orthotomic about a pole (thesis 6.3.2; K = 2 orthotomic, 1 pedal): {'mapping', 'pole', 'k', "
        "'tolerance', 'exact', 'deviation', 'curve'}.");
  m.def("polar_map", &polar_map, py::arg("curve"), py::arg("centre"), py::kw_only(), py::arg("radius") = 1.0,
        py::arg("tolerance") = py::none(),
        "Polar map of a plane curve about a circle (thesis 6.3.2; inflections become cusps): {'mapping', "
        "'centre', 'radius', 'tolerance', 'exact', 'deviation', 'curve'}.");
  m.def("hermite_frenet", &hermite_frenet, py::arg("document"),
        "The C3 septic Hermite curve through Frenet handles {'handles': [{'point', 'tangent', 'normal', "
        "'curvature', 'torsion'}], 'parameters'?} fixing κ, N and τ at every handle (docs/formats.md).");
}

}  // namespace hula::python
