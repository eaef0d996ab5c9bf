// SPDX-License-Identifier: MIT
// The thesis's curve studies from Python: a setup is the dict a study file
// holds (docs/formats.md), read by the same studies/io codecs as `hula
// fair-knots` and `hula match-curvature`, and run with the GIL released. The
// result is a dict of plain values and arrays; the Python layer wraps it in a
// StudyResult (hulahoops/studies.py).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "hula/io/fair_knots_study_file.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/match_study_file.hpp"
#include "hula/io/path_resolver.hpp"
#include "hula/io/study_file.hpp"
#include "hula/studies/knot_fairing.hpp"

namespace hula::python {

namespace py = pybind11;

namespace {

// A study setup: a dict converted value by value, or JSON text (a str) parsed once where it comes in.
io::Json setup_value(const py::handle& setup) {
  if (py::isinstance<py::str>(setup)) return io::json::parse_json_text(setup.cast<std::string>(), "study");
  return from_python(setup, "setup");
}

py::dict evaluation(const studies::ParameterEvaluation& e) {
  py::dict d;
  d["parameters"] = to_array(e.parameters);
  d["energy"] = e.energy;
  d["bending"] = e.bending;
  d["variation"] = e.variation;
  d["curve"] = py::cast(e.curve);
  return d;
}

// The run as the CLI prints it (io::fairing_result_to_json), with the parameters as an array, the curve as
// a NurbsCurve and the convergence graph added.
py::dict fairing(const studies::FairingResult& r, double chord_energy) {
  py::dict d = to_python(io::fairing_result_to_json(r, chord_energy));
  d["parameters"] = to_array(r.best.parameters);
  d["curve"] = py::cast(r.best.curve);
  d["convergence"] = to_array(r.convergence);
  return d;
}

py::dict fair_knots(const py::handle& setup) {
  const io::StudyDocument doc = io::study_from_json(setup_value(setup), "fair-knots");
  const studies::FairKnotsStudy study = io::fair_knots_study_from_json(doc);
  const studies::KnotFairingSetup& s = study.setup;
  std::optional<studies::ParameterEvaluation> chord, given;
  std::optional<studies::EnergyMap> map;
  std::optional<studies::FairingResult> ga, det;
  {
    const py::gil_scoped_release release;
    const std::vector<double> start = studies::chord_length_parameters(s);
    chord = studies::evaluate_parameters(s, start);
    if (study.parameters) given = studies::evaluate_parameters(s, *study.parameters);
    if (study.map) map = studies::energy_map(s, start, *study.map);
    const bool run_ga = study.method == studies::FairingMethod::Ga || study.method == studies::FairingMethod::Both;
    const bool run_det =
        study.method == studies::FairingMethod::Deterministic || study.method == studies::FairingMethod::Both;
    if (run_ga) ga = studies::fair_knots_ga(s, start, study.ga);
    if (run_det) det = studies::fair_knots_deterministic(s, start, study.deterministic);
  }
  py::dict out;
  out["study"] = to_python(io::fair_knots_study_to_json(study));
  out["energy"] = std::string(studies::fairing_energy_name(s.energy));
  out["chord_length"] = evaluation(*chord);
  if (given) out["given"] = evaluation(*given);
  if (ga) out["ga"] = fairing(*ga, chord->energy);
  if (det) out["deterministic"] = fairing(*det, chord->energy);
  if (map) {
    py::dict m;
    m["k1"] = to_array(map->k1);
    m["k2"] = to_array(map->k2);
    Doubles e({static_cast<py::ssize_t>(map->k2.size()), static_cast<py::ssize_t>(map->k1.size())});
    std::copy(map->energy.begin(), map->energy.end(), e.mutable_data());
    m["energy"] = e;
    m["min_energy"] = map->min_energy;
    m["min_k1"] = map->min_k1;
    m["min_k2"] = map->min_k2;
    out["map"] = m;
  }
  return out;
}

// The match result as the CLI prints it (io::match_result_to_json), as Python objects. Profile files named
// in the setup are read relative to `base`, as the CLI reads them relative to the study file.
py::object match_curvature(const py::handle& setup, const std::string& base, std::optional<std::string> method) {
  const io::StudyDocument doc = io::study_from_json(setup_value(setup), "match-curvature");
  io::MatchStudyFile file = io::match_study_from_json(doc, io::relative_to(std::filesystem::path(base)));
  studies::MatchStudy& study = file.study;
  if (method) study.method = studies::match_method_from_name(*method, "method");
  io::Json out;
  {
    const py::gil_scoped_release release;
    const studies::CurvatureMatch match(study.setup);
    const studies::MatchResult result = studies::run_curvature_match(match, study, false);
    out = io::match_result_to_json(match, file, result);
  }
  return to_python(out);
}

}  // namespace

void register_studies(py::module_& m) {
  m.def("fair_knots", &fair_knots, py::arg("setup"));
  m.def("match_curvature", &match_curvature, py::arg("setup"), py::arg("base"), py::arg("method") = py::none());
}

}  // namespace hula::python
