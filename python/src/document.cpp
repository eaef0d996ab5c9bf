// SPDX-License-Identifier: MIT
// hulahoops._core.Document: the Oli curve document (.hula file) as
// `hula doc` drives it — create/open, add (curves, point sets), show, set (curve, attribute, moved
// control point), remove, undo, redo, history, run a study. Every change is one
// transaction: it applies whole or raises the hulahoops.Error of its code and
// leaves the file as it was. Values cross as JSON text (the curve-file and
// `hula doc` formats); hulahoops/document.py turns them into dicts.
#include "hula/oli/document.hpp"

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "hula/core/error.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"
#include "hula/io/points_file.hpp"
#include "hula/oli/study_run.hpp"

namespace hula::python {

namespace py = pybind11;

namespace {

using Json = io::json::Json;

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
          [](PyDocument& d, const py::handle& setup, const std::string& base) {
            const Json study = from_python(setup, "study");
            oli::StudyRunResult ran;
            commit(d.doc(), "run study", [&](oli::Edit& e) { ran = oli::run_study(e, study, base); });
            Json out = ran.result;
            out["study_label"] = ran.study.value;
            Json curves = Json::array();
            for (const oli::Label l : ran.curves) curves.push_back(l.value);
            out["result_labels"] = std::move(curves);
            out["revision"] = d.doc().revision();
            return to_python(out);
          },
          py::arg("study"), py::arg("base") = "");
}

}  // namespace hula::python
