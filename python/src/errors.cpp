// SPDX-License-Identifier: MIT
// hula::Error crosses into Python as an instance of the hulahoops.errors class
// of its code (InvalidArgumentError, ParseError, ...), all subclasses of
// hulahoops.Error, carrying `code` (the Errc name), `message` and `where` (a
// dict with the set fields of hula::ErrorWhere), the same triple the CLI and
// the HTTP API report (docs/errors.md).
#include <pybind11/pybind11.h>

#include <exception>
#include <string>

#include "bindings.hpp"
#include "hula/core/error.hpp"

namespace hula::python {

namespace py = pybind11;

namespace {

py::dict where_to_dict(const ErrorWhere& w) {
  py::dict d;
  if (!w.field.empty()) d["field"] = w.field;
  if (w.index) d["index"] = *w.index;
  if (w.component) d["component"] = *w.component;
  if (w.line) d["line"] = *w.line;
  if (w.column) d["column"] = *w.column;
  return d;
}

}  // namespace

void register_errors(py::module_& m) {
  (void)m;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      const std::string code(errc_name(e.code()));
      const py::object cls = py::module_::import("hulahoops.errors").attr("error_class")(code);
      const py::object instance = cls(code, e.message(), where_to_dict(e.where()));
      PyErr_SetObject(cls.ptr(), instance.ptr());
    }
  });
}

}  // namespace hula::python
