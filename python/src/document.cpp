// SPDX-License-Identifier: MIT
// hulahoops._core.Document: the Oli curve document (.hula file) as
// `hula doc` drives it — create/open, add (curves, point sets), show, set (curve, attribute, moved
// control point), remove, undo, redo, history, run a study (interruptible by Ctrl-C, the best so far
// stored as `hula doc run` stores it), export and import (`hula convert`'s halves), a curve's stored
// constraints (oli/constraints.hpp) and design variables read and written (oli/variables.hpp). Every
// change is one transaction: it applies whole or raises the hulahoops.Error of its code and leaves the
// file as it was. Values cross value by value (from_python / to_python, no JSON text);
// hulahoops/document.py is the documented wrapper.
#include "hula/oli/document.hpp"

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "hula/core/error.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"
#include "hula/io/points_file.hpp"
#include "hula/oli/constraints.hpp"
#include "hula/oli/file_convert.hpp"
#include "hula/oli/study_run.hpp"
#include "hula/oli/variables.hpp"
#include "hula/optim/run_log.hpp"
#include "interrupt.hpp"

namespace hula::python {

namespace py = pybind11;

namespace {

using Json = io::json::Json;
namespace j = io::json;

// A document the Python object owns until close() (which releases the file's writer lock).
class PyDocument {
 public:
  explicit PyDocument(oli::Document doc) : doc_(std::move(doc)) {}

  oli::Document& doc() {
    if (!doc_) throw Error(Errc::InvalidArgument, "the document is closed", {.field = "document"});
    return *doc_;
  }
  void close() { doc_.reset(); }
  [[nodiscard]] bool closed() const { return !doc_; }

 private:
  std::optional<oli::Document> doc_;
};

oli::Label label_of(std::uint64_t value) {
  if (value == 0) throw Error(Errc::InvalidArgument, "label 0 is not a label (labels start at 1)", {.field = "label"});
  return oli::Label{value};
}

// Runs one transaction; raises its error (the document is then unchanged).
std::uint64_t commit(oli::Document& doc, std::string_view name, const std::function<void(oli::Edit&)>& body) {
  doc.transact(name, body).throw_if_failed();
  return doc.revision();
}

// The constraints stored with curve `label`; a missing label or another kind of entity is the error
// Edit::set_constraints gives (Entity::curve names the kind).
std::vector<oli::Constraint> constraints_of(const oli::Document& doc, oli::Label label) {
  const oli::Entity e = doc.get(label);
  (void)e.curve();
  return e.constraints();
}

// One variable selection from a dict {"label", "kind", "indices"?, "axes"?, "bounds"?: {"mode", "lower",
// "upper"}} with oli::VariableSelection's names and defaults; errors name selections[i].member.
oli::VariableSelection selection_of(const Json& item, const j::JsonPath& at) {
  j::reject_unknown_members(item, at, {"label", "kind", "indices", "axes", "bounds"});
  oli::VariableSelection s;
  s.label = oli::Label{static_cast<std::uint64_t>(j::get_integer(
      j::require_member(item, at, "label"), at.member("label"), 1, std::numeric_limits<long long>::max()))};
  const std::string kind = j::get_string(j::require_member(item, at, "kind"), at.member("kind"));
  std::string names;
  bool known = false;
  for (const auto k :
       {oli::VariableKind::ControlPoints, oli::VariableKind::Weights, oli::VariableKind::InteriorKnots,
        oli::VariableKind::DataPoints, oli::VariableKind::EndTangents, oli::VariableKind::LawConstants}) {
    names += (names.empty() ? "" : ", ") + std::string(oli::variable_kind_name(k));
    if (oli::variable_kind_name(k) == kind) {
      s.kind = k;
      known = true;
    }
  }
  if (!known)
    throw Error(Errc::ParseError,
                at.member("kind").text + " = " + j::quote(kind) + " is not a variable kind (" + names + ")",
                at.member("kind").where);
  if (const Json* v = j::optional_member(item, "indices")) {
    const Json& list = j::get_array(*v, at.member("indices"));
    for (std::size_t k = 0; k < list.size(); ++k)
      s.indices.push_back(static_cast<std::size_t>(
          j::get_integer(list[k], at.member("indices").element(k), 0, std::numeric_limits<long long>::max())));
  }
  if (const Json* v = j::optional_member(item, "axes")) s.axes = j::get_string(*v, at.member("axes"));
  if (const Json* b = j::optional_member(item, "bounds")) {
    const j::JsonPath bp = at.member("bounds");
    j::reject_unknown_members(*b, bp, {"mode", "lower", "upper"});
    if (const Json* m = j::optional_member(*b, "mode")) {
      const std::string mode = j::get_string(*m, bp.member("mode"));
      if (mode != "relative" && mode != "absolute")
        throw Error(Errc::ParseError, bp.member("mode").text + " = " + j::quote(mode) + " must be relative or absolute",
                    bp.member("mode").where);
      s.bounds.mode = mode == "absolute" ? oli::BoundMode::Absolute : oli::BoundMode::Relative;
    }
    if (const Json* v = j::optional_member(*b, "lower")) s.bounds.lower = j::get_number(*v, bp.member("lower"));
    if (const Json* v = j::optional_member(*b, "upper")) s.bounds.upper = j::get_number(*v, bp.member("upper"));
  }
  return s;
}

oli::VariableSet variable_set_of(const py::handle& selections) {
  const Json value = from_python(selections, "selections");
  const j::JsonPath at = j::root_path("selections");
  const Json& list = j::get_array(value, at);
  oli::VariableSet set;
  for (std::size_t i = 0; i < list.size(); ++i) set.selections.push_back(selection_of(list[i], at.element(i)));
  return set;
}

std::vector<oli::Label> labels_of(const std::vector<std::uint64_t>& values) {
  std::vector<oli::Label> out;
  for (const std::uint64_t v : values) out.push_back(label_of(v));
  return out;
}

}  // namespace

void register_document(py::module_& m) {
  py::class_<PyDocument>(m, "Document")
      .def_static(
          "create",
          [](const std::string& path, const std::string& backend, bool force) {
            oli::DocumentOptions options;
            options.backend = backend;
            return PyDocument(oli::Document::create(path, options, force));
          },
          py::arg("path"), py::arg("backend") = "native", py::arg("force") = false)
      .def_static(
          "open",
          [](const std::string& path, bool read_only) {
            return PyDocument(
                oli::Document::open(path, read_only ? oli::OpenMode::ReadOnly : oli::OpenMode::ReadWrite));
          },
          py::arg("path"), py::arg("read_only") = false)
      .def("close", &PyDocument::close)
      .def_property_readonly("closed", &PyDocument::closed)
      .def_property_readonly("revision", [](PyDocument& d) { return d.doc().revision(); })
      .def_property_readonly("backend", [](PyDocument& d) { return d.doc().options().backend; })
      .def_property_readonly("can_undo", [](PyDocument& d) { return d.doc().can_undo(); })
      .def_property_readonly("can_redo", [](PyDocument& d) { return d.doc().can_redo(); })
      .def("labels",
           [](PyDocument& d) {
             std::vector<std::uint64_t> out;
             for (const oli::Label l : d.doc().labels()) out.push_back(l.value);
             return out;
           })
      .def(
          "add_curve",
          [](PyDocument& d, const py::handle& value, const std::string& name) {
            const curve::Curve curve = curve_value(value);
            oli::Attributes attributes;
            attributes.name = name;
            oli::Label label;
            commit(d.doc(), "add curve", [&](oli::Edit& e) { label = e.add_curve(curve, attributes); });
            return label.value;
          },
          py::arg("curve"), py::arg("name") = "")
      .def(
          "add_points",
          [](PyDocument& d, const py::handle& rows, const std::string& name) {
            const Points p = as_points(rows, "points");
            io::PointSet points{p.points, p.dimension};
            oli::Attributes attributes;
            attributes.name = name;
            oli::Label label;
            commit(d.doc(), "add points", [&](oli::Edit& e) { label = e.add_point_set(points, attributes); });
            return label.value;
          },
          py::arg("points"), py::arg("name") = "")
      .def("show", [](PyDocument& d,
                      std::uint64_t label) { return to_python(oli::entity_to_json(d.doc().get(label_of(label)))); })
      .def("set_curve",
           [](PyDocument& d, std::uint64_t label, const py::handle& value) {
             const oli::Label l = label_of(label);
             const curve::Curve curve = curve_value(value);
             return commit(d.doc(), "set curve", [&](oli::Edit& e) { e.set_curve(l, curve); });
           })
      .def("set_attribute",
           [](PyDocument& d, std::uint64_t label, const std::string& key, const py::handle& attribute) {
             const oli::Label l = label_of(label);
             const Json value = from_python(attribute, "value");
             return commit(d.doc(), "set " + key, [&](oli::Edit& e) { e.set_attribute(l, key, value); });
           })
      .def("move_point",
           [](PyDocument& d, std::uint64_t label, std::size_t index, double x, double y, double z) {
             const oli::Label l = label_of(label);
             return commit(d.doc(), "move point", [&](oli::Edit& e) { e.move_point(l, index, Vec3{x, y, z}); });
           })
      .def("remove",
           [](PyDocument& d, std::uint64_t label) {
             const oli::Label l = label_of(label);
             return commit(d.doc(), "remove", [&](oli::Edit& e) { e.remove(l); });
           })
      .def("undo",
           [](PyDocument& d) {
             d.doc().undo().throw_if_failed();
             return d.doc().revision();
           })
      .def("redo",
           [](PyDocument& d) {
             d.doc().redo().throw_if_failed();
             return d.doc().revision();
           })
      .def("history",
           [](PyDocument& d) {
             Json out = Json::array();
             for (const oli::HistoryEntry& h : d.doc().history()) {
               Json changed = Json::array();
               for (const oli::Label l : h.changed) changed.push_back(l.value);
               out.push_back(Json{{"revision", h.revision},
                                  {"name", h.name},
                                  {"time", h.time},
                                  {"changed", std::move(changed)},
                                  {"applied", h.applied}});
             }
             return to_python(out);
           })
      .def(
          "run",
          [](PyDocument& d, const py::handle& setup, const std::string& base, const py::object& progress) {
            // `hula doc run`'s three phases: the references resolved here, the study computed on a worker
            // thread that Ctrl-C (or a true return of `progress`) stops with its best so far, then that run
            // stored in one transaction — an interrupted run is stored too, as "cancelled".
            oli::PreparedStudy prepared = oli::prepare_study(d.doc(), from_python(setup, "study"));
            Interruptible job;
            oli::StudyRunOptions options;
            options.cancel = job.token();
            if (!progress.is_none())
              options.on_progress = [&](const optim::GenerationLog& g, const studies::StudyReport& report) {
                const py::gil_scoped_acquire gil;
                if (py::bool_(progress(g.generation, optim::statistics(g).best, report.evaluations))) job.stop();
              };
            oli::ComputedStudy computed =
                job.run([&] { return oli::compute_study(std::move(prepared), base, options); });
            oli::StudyRunResult ran;
            commit(d.doc(), "run study", [&](oli::Edit& e) { ran = oli::commit_study(e, std::move(computed)); });
            Json out = ran.result;
            out["cancelled"] = ran.cancelled;
            out["study_label"] = ran.study.value;
            Json curves = Json::array();
            for (const oli::Label l : ran.curves) curves.push_back(l.value);
            out["result_labels"] = std::move(curves);
            out["revision"] = d.doc().revision();
            py::dict result = to_python(out);
            if (!job.interrupt().is_none()) result["interrupt"] = job.interrupt();
            return result;
          },
          py::arg("study"), py::arg("base") = "", py::arg("progress") = py::none())
      .def(
          "export_file",
          [](PyDocument& d, const std::vector<std::uint64_t>& labels, const py::handle& path,
             const std::optional<std::string>& format) {
            // `hula convert`'s writing half (the JSON, DXF, STEP and IGES writers of `hula doc export`).
            const std::vector<oli::Label> ls = labels_of(labels);
            const std::filesystem::path output =
                py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
            oli::ConvertOptions options;
            if (format) options.output_format = oli::file_format_from_name(*format);
            oli::ConvertReport report;
            {
              const py::gil_scoped_release release;
              oli::write_curve_file(d.doc(), ls, output, options, report);
            }
            py::dict out;
            out["format"] = std::string(oli::file_format_name(report.output_format));
            out["curves"] = report.curves;
            out["skipped"] = report.skipped;
            out["max_deviation"] = report.max_deviation;
            out["warnings"] = report.warnings;
            return out;
          },
          py::arg("labels"), py::arg("path"), py::arg("format") = py::none())
      .def(
          "import_file",
          [](PyDocument& d, const py::handle& path, const std::optional<std::string>& format) {
            // `hula convert`'s reading half: the file's entities added with their names, colours, layers.
            const std::filesystem::path input =
                py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
            oli::ConvertOptions options;
            if (format) options.input_format = oli::file_format_from_name(*format);
            oli::ConvertReport report;
            std::vector<oli::Label> labels;
            {
              const py::gil_scoped_release release;
              labels = oli::read_curve_file(d.doc(), input, options, report);
            }
            py::dict out;
            std::vector<std::uint64_t> values;
            for (const oli::Label l : labels) values.push_back(l.value);
            out["labels"] = values;
            out["format"] = std::string(oli::file_format_name(report.input_format));
            out["warnings"] = report.warnings;
            out["revision"] = d.doc().revision();
            return out;
          },
          py::arg("path"), py::arg("format") = py::none())
      .def("constraints",
           [](PyDocument& d, std::uint64_t label) {
             return to_python(oli::constraints_to_json(constraints_of(d.doc(), label_of(label))));
           })
      .def("set_constraints",
           [](PyDocument& d, std::uint64_t label, const py::handle& constraints) {
             const oli::Label l = label_of(label);
             std::vector<oli::Constraint> list = oli::constraints_from_json(from_python(constraints, "constraints"));
             return commit(d.doc(), "set constraints", [&](oli::Edit& e) { e.set_constraints(l, list); });
           })
      .def("add_constraint",
           [](PyDocument& d, std::uint64_t label, const py::handle& constraint) {
             const oli::Label l = label_of(label);
             const Json one = Json::array({from_python(constraint, "constraint")});
             const oli::Constraint added = oli::constraints_from_json(one).front();
             return commit(d.doc(), "add constraint", [&](oli::Edit& e) {
               std::vector<oli::Constraint> list = e.get(l).constraints();
               list.push_back(added);
               e.set_constraints(l, std::move(list));
             });
           })
      .def("remove_constraint",
           [](PyDocument& d, std::uint64_t label, std::size_t index) {
             const oli::Label l = label_of(label);
             return commit(d.doc(), "remove constraint", [&](oli::Edit& e) {
               std::vector<oli::Constraint> list = e.get(l).constraints();
               if (index >= list.size())
                 throw Error(Errc::InvalidArgument,
                             "index = " + std::to_string(index) + " is out of range: entity " +
                                 std::to_string(l.value) + " has " + std::to_string(list.size()) + " constraints",
                             {.field = "index"});
               list.erase(list.begin() + static_cast<std::ptrdiff_t>(index));
               e.set_constraints(l, std::move(list));
             });
           })
      .def("check_constraints",
           [](PyDocument& d, std::uint64_t label) {
             const oli::Entity e = d.doc().get(label_of(label));
             py::list out;
             for (const oli::ConstraintResidual& r : oli::check_constraints(e.curve(), e.constraints())) {
               py::dict item;
               item["index"] = r.index;
               item["kind"] = std::string(oli::constraint_kind_name(r.kind));
               item["residual"] = r.residual;
               item["satisfied"] = r.satisfied;
               out.append(item);
             }
             return out;
           })
      .def("variables",
           [](PyDocument& d, const py::handle& selections) {
             const oli::VariableValues v = oli::read_variables(d.doc(), variable_set_of(selections));
             py::dict out;
             out["names"] = v.names;
             out["values"] = to_array(v.values);
             out["lower"] = to_array(v.lower);
             out["upper"] = to_array(v.upper);
             return out;
           })
      .def("set_variables", [](PyDocument& d, const py::handle& selections, const py::handle& values) {
        const oli::VariableSet set = variable_set_of(selections);
        const std::vector<double> v = as_vector(values, "values");
        return commit(d.doc(), "set variables", [&](oli::Edit& e) { oli::write_variables(e, set, v); });
      });
}

}  // namespace hula::python
