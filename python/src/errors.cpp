// SPDX-License-Identifier: MIT
// hula::Error crosses into Python as an instance of the hulahoops.errors class
// of its code (InvalidArgumentError, ParseError, ...), all subclasses of
// hulahoops.Error, carrying `code` (the Errc name), `message` and `where` (a
// dict with the set fields of hula::ErrorWhere), the same triple the CLI and
// the HTTP API report (docs/errors.md). The message and the field are given
// their Python spelling at this boundary: the C++ enumerators a message
// names become the keyword argument that asks for them (Domain::Extrapolate:
// domain="extrapolate") and a command-line option that names a file becomes
// the argument's name (--output: path).
#include <pybind11/pybind11.h>

#include <exception>
#include <string>
#include <string_view>
#include <utility>

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

// C++ spellings engine messages use, and the Python spelling of the same choice.
constexpr std::pair<std::string_view, std::string_view> kSpellings[] = {
    {"Domain::Extrapolate", "domain=\"extrapolate\""},
    {"Domain::Clamp", "domain=\"clamp\""},
    {"Domain::Strict", "domain=\"strict\""},
    {"Side::Left", "side=\"left\""},
    {"Side::Right", "side=\"right\""},
    {"an EndCondition::Kind value", "an end condition"},
};

// Command-line options (ErrorWhere.field holds them without their dashes) that name a Python argument of
// another name.
constexpr std::pair<std::string_view, std::string_view> kArguments[] = {{"output", "path"}, {"input", "path"}};

void replace_all(std::string& text, std::string_view from, std::string_view to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

// An engine message and field in their Python spelling: "--output 'x': ..." with field "output" becomes
// "path 'x': ..." with field "path".
std::pair<std::string, std::string> python_spelling(std::string message, std::string field) {
  for (const auto& [cpp, python] : kSpellings) replace_all(message, cpp, python);
  for (const auto& [option, argument] : kArguments) {
    replace_all(message, "--" + std::string(option), argument);
    if (field == option) field = argument;
  }
  return {std::move(message), std::move(field)};
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
      const auto [message, field] = python_spelling(e.message(), e.where().field);
      py::dict where = where_to_dict(e.where());
      if (!field.empty()) where["field"] = field;
      const py::object instance = cls(code, message, where);
      PyErr_SetObject(cls.ptr(), instance.ptr());
    }
  });
}

}  // namespace hula::python
