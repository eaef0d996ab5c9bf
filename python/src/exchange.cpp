// SPDX-License-Identifier: MIT
// hulahoops.read / hulahoops.write: curve files by extension (JSON curve
// files and hula-documents, STEP, IGES, DXF; SVG written only) through the
// halves of `hula convert` (oli::read_curve_file, oli::write_curve_file) on
// an in-memory document, so a file written here is the file `hula convert`
// writes. No format code lives here.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "hula/core/error.hpp"
#include "hula/oli/file_convert.hpp"
#ifdef HULA_WITH_OCCT
#include "hula/oli/exchange/exchange.hpp"
#endif

namespace hula::python {

namespace py = pybind11;

namespace {

std::filesystem::path path_of(const py::handle& path) {
  return py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
}

oli::ConvertOptions options_of(const std::optional<std::string>& format, bool output, std::optional<double> tolerance) {
  oli::ConvertOptions o;
  if (format) (output ? o.output_format : o.input_format) = oli::file_format_from_name(*format);
  if (tolerance) o.svg_tolerance = *tolerance;
  return o;
}

// The curves of a file, in file order, as NURBS (a law or natural-equation curve of a JSON file: its NURBS
// approximation); point sets and studies are left out.
py::list read(const py::handle& path, const std::optional<std::string>& format) {
  const std::filesystem::path input = path_of(path);
  const oli::ConvertOptions options = options_of(format, false, std::nullopt);
  oli::Document document;
  oli::ConvertReport report;
  std::vector<oli::Label> labels;
  {
    const py::gil_scoped_release release;
    labels = oli::read_curve_file(document, input, options, report);
  }
  py::list out;
  for (const oli::Label l : labels) {
    const oli::Entity e = document.get(l);
    if (e.kind() == oli::EntityKind::Curve) out.append(py::cast(e.curve().nurbs()));
  }
  return out;
}

// Writes one curve or a sequence of curves (NurbsCurve, curve-file dict or path) with optional names.
py::dict write(const py::handle& curves, const py::handle& path, const std::optional<std::vector<std::string>>& names,
               const std::optional<std::string>& format, std::optional<double> tolerance) {
  std::vector<curve::Curve> values;
  const bool many = py::isinstance<py::list>(curves) || py::isinstance<py::tuple>(curves);
  if (many)
    for (const py::handle c : curves) values.push_back(curve_value(c));
  else
    values.push_back(curve_value(curves));
  if (names && names->size() != values.size())
    throw Error(
        Errc::InvalidArgument,
        "names has " + std::to_string(names->size()) + " entries for " + std::to_string(values.size()) + " curves",
        {.field = "names"});
  const std::filesystem::path output = path_of(path);
  const oli::ConvertOptions options = options_of(format, true, tolerance);
  oli::ConvertReport report;
  {
    const py::gil_scoped_release release;
    oli::Document document;
    std::vector<oli::Label> labels;
    document
        .transact("write",
                  [&](oli::Edit& e) {
                    for (std::size_t i = 0; i < values.size(); ++i) {
                      oli::Attributes a;
                      a.name = names ? (*names)[i] : (values.size() == 1 ? "curve" : "curve-" + std::to_string(i + 1));
                      labels.push_back(e.add_curve(values[i], a));
                    }
                  })
        .throw_if_failed();
    oli::write_curve_file(document, labels, output, options, report);
  }
  py::dict d;
  d["format"] = std::string(oli::file_format_name(report.output_format));
  d["curves"] = report.curves;
  d["max_deviation"] = report.max_deviation;
  d["warnings"] = report.warnings;
  return d;
}

}  // namespace

void register_exchange(py::module_& m) {
  m.def("read", &read, py::arg("path"), py::kw_only(), py::arg("format") = py::none(),
        R"doc(The curves of a file, in file order: a JSON curve file or hula-document
(.json), STEP (.step, .stp), IGES (.iges, .igs) or DXF (.dxf, SPLINE
entities), chosen by the extension or by ``format`` ("json", "step",
"step-ap214", "step-ap242", "iges", "dxf"). Read exactly as ``hula convert``
reads its input. Law and natural-equation curves of a JSON file come as their
NURBS approximation; point sets and studies are left out.

Raises:
    InvalidArgumentError: unknown extension or format, or an SVG file (written only).
    IoError, ParseError: the file cannot be read or parsed (naming it).
    UnsupportedError: STEP/IGES in a build without Open CASCADE.)doc");
  m.def("write", &write, py::arg("curves"), py::arg("path"), py::kw_only(), py::arg("names") = py::none(),
        py::arg("format") = py::none(), py::arg("tolerance") = py::none(),
        R"doc(Writes one curve or a list of curves (NurbsCurve, curve-file dict or path)
to a file in the format of its extension or ``format``: JSON curve file
(one curve) or hula-document (several), STEP (AP214; "step-ap242" by name),
IGES, DXF (SPLINE entities) or SVG (exact cubic Bézier paths for degree <= 3,
within ``tolerance`` model units otherwise). Written exactly as ``hula
convert`` writes its output, atomically or not at all. ``names`` (one per
curve) are the entity names written (STEP product names, IGES and DXF
names); default "curve" or "curve-1", "curve-2", ...

Returns ``{"format", "curves", "max_deviation", "warnings"}``.

Raises:
    InvalidArgumentError: unknown extension or format, names of the wrong length.
    IoError: the file cannot be written (nothing is).)doc");
  m.def(
      "exchange_helper",
      []() -> std::optional<std::string> {
#ifdef HULA_WITH_OCCT
        return oli::default_exchange_helper().string();
#else
        return std::nullopt;
#endif
      },
      R"doc(The path of the ``hula-exchange`` helper that writes and reads STEP and IGES
(Open CASCADE, in a process of its own): $HULA_EXCHANGE_HELPER if set, else
the one installed beside this module (a wheel ships it in the package), else
beside the running executable, else the build tree's. None in a build without
Open CASCADE.)doc");
}

}  // namespace hula::python
