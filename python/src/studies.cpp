// SPDX-License-Identifier: MIT
// The thesis's curve studies from Python: a setup is the dict a study file
// holds (docs/formats.md), run by oli::run_study (the runner of `hula
// fair-knots`, `hula match-curvature` and the document's study runs) with the
// GIL released. The result is the result document every door gives, converted
// value by value, with arrays and curves from the run's typed values; the
// Python layer wraps it in a StudyResult (hulahoops/studies.py). Ctrl-C and
// the progress callback stop the run with its best so far through the
// runner's cancellation token (interrupt.hpp); the signal handler's exception
// comes back as "interrupt" for the Python layer to raise with the result.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <variant>

#include "arrays.hpp"
#include "bindings.hpp"
#include "hula/core/error.hpp"
#include "hula/io/fit_study_file.hpp"
#include "hula/io/json_text.hpp"
#include "hula/io/path_resolver.hpp"
#include "hula/io/study_file.hpp"
#include "hula/oli/study_runner.hpp"
#include "interrupt.hpp"

namespace hula::python {

namespace py = pybind11;

namespace {

// A study setup: a dict converted value by value, or JSON text (a str) parsed once where it comes in.
io::Json setup_value(const py::handle& setup) {
  if (py::isinstance<py::str>(setup)) return io::json::parse_json_text(setup.cast<std::string>(), "study");
  return from_python(setup, "setup");
}

// oli::run_study, the runner of every door, on a worker thread with the GIL released (Interruptible); no log
// is kept. `progress(generation, best, evaluations)` is called after every generation of the study's
// optimisers (evaluations counted across them); a true return stops the run with its best so far.
oli::StudyOutcome run(const io::StudyDocument& doc, const std::filesystem::path& base, Interruptible& job,
                      const py::object& progress) {
  oli::StudyRunOptions options;
  options.keep_log = false;
  options.cancel = job.token();
  if (!progress.is_none())
    options.on_progress = [&](const optim::GenerationLog& g, const studies::StudyReport& report) {
      const py::gil_scoped_acquire gil;
      if (py::bool_(progress(g.generation, optim::statistics(g).best, report.evaluations))) job.stop();
    };
  return job.run([&] { return oli::run_study(doc, io::relative_to(base), options); });
}

// The result dict with the signal handler's exception under "interrupt" when Ctrl-C stopped the run.
py::dict with_interrupt(py::dict out, const Interruptible& job) {
  if (!job.interrupt().is_none()) out["interrupt"] = job.interrupt();
  return out;
}

// An evaluation of the result document with its parameters as an array and its curve as a NurbsCurve.
void with_values(py::dict d, const studies::ParameterEvaluation& e) {
  d["parameters"] = to_array(e.parameters);
  d["curve"] = py::cast(e.curve);
}

// The result `hula fair-knots` prints, as Python objects: parameters as arrays, curves as NurbsCurve, each
// optimiser's convergence graph added, and the map with its grid (k1, k2, the energy as a (k2, k1) array with
// NaN outside k1 < k2, and its minimum).
py::dict fair_knots(const py::handle& setup, const py::object& progress) {
  Interruptible job;
  const oli::StudyOutcome ran = run(io::study_from_json(setup_value(setup), "fair-knots"), ".", job, progress);
  const studies::FairKnotsOutcome& o = std::get<oli::FairKnotsValues>(ran.values).outcome;
  py::dict out = to_python(ran.result);
  with_values(out["chord_length"], o.chord_length);
  if (o.given) with_values(out["given"], *o.given);
  for (const auto& [name, r] : {std::pair{"ga", &o.ga}, std::pair{"deterministic", &o.deterministic}})
    if (*r) {
      py::dict d = out[name];
      with_values(d, (*r)->best);
      d["convergence"] = to_array((*r)->convergence);
    }
  if (o.map) {
    py::dict m = out["map"];
    m["k1"] = to_array(o.map->k1);
    m["k2"] = to_array(o.map->k2);
    Doubles e({static_cast<py::ssize_t>(o.map->k2.size()), static_cast<py::ssize_t>(o.map->k1.size())});
    std::copy(o.map->energy.begin(), o.map->energy.end(), e.mutable_data());
    m["energy"] = e;
    m["min_energy"] = o.map->min_energy;
    m["min_k1"] = o.map->min_k1;
    m["min_k2"] = o.map->min_k2;
  }
  return with_interrupt(out, job);
}

// The result `hula match-curvature` prints, as Python objects. Profile files named in the setup are read
// relative to `base`, as the CLI reads them relative to the study file; `method` replaces the setup's.
py::dict match_curvature(const py::handle& setup, const std::string& base, std::optional<std::string> method,
                         const py::object& progress) {
  io::Json value = setup_value(setup);
  if (method) {
    if (!value.is_object()) throw Error(Errc::ParseError, "a study setup must be a JSON object", {.field = "setup"});
    value["method"] = *method;
  }
  Interruptible job;
  const oli::StudyOutcome ran = run(io::study_from_json(std::move(value), "match-curvature"), base, job, progress);
  return with_interrupt(to_python(ran.result), job);
}

// The result `hula fit` prints for a "fit" study (studies::fit_scan, io::fit_result_to_json), with the faired
// curve as a NurbsCurve under "curve". Points files named in the setup resolve against `base`.
// `progress(generation, deviation, solves)` is called after each candidate curve of the search and once
// with the result (ScanFitOptions::on_generation); its return value is not read (a fit has no best so far
// to stop with), an exception it raises ends the fit and propagates.
py::dict fit(const py::handle& setup, const std::string& base, const py::object& progress) {
  io::FitStudy study = io::fit_study_from_json(io::study_from_json(setup_value(setup), "fit"), io::relative_to(base));
  if (!progress.is_none())
    study.options.on_generation = [&progress](const optim::GenerationLog& g) {
      const py::gil_scoped_acquire gil;
      (void)progress(g.generation, optim::statistics(g).best, g.evaluations);
    };
  const studies::ScanFitResult r = [&] {
    const py::gil_scoped_release release;
    return studies::fit_scan(study.points, study.options);
  }();
  py::dict out = to_python(io::fit_result_to_json(r, study.options));
  out["curve"] = py::cast(r.faired);
  return out;
}

}  // namespace

void register_studies(py::module_& m) {
  m.def("fair_knots", &fair_knots, py::arg("setup"), py::arg("progress") = py::none());
  m.def("fit", &fit, py::arg("setup"), py::arg("base"), py::arg("progress") = py::none(),
        "The result of `hula fit` for a \"fit\" study dict (docs/formats.md): scanned points to a class-A curve\n"
        "(thesis ch. 3), with the faired NurbsCurve under \"curve\".");
  m.def("match_curvature", &match_curvature, py::arg("setup"), py::arg("base"), py::arg("method") = py::none(),
        py::arg("progress") = py::none());
}

}  // namespace hula::python
