// SPDX-License-Identifier: MIT
#include "hula/oli/file_convert.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"
#include "hula/oli/json_exchange.hpp"
#ifdef HULA_WITH_OCCT
#include "hula/oli/cad_exchange.hpp"
#endif

namespace hula::oli {
namespace {

namespace fs = std::filesystem;

#ifdef HULA_WITH_OCCT
ExchangeFormat exchange_format(FileFormat f) {
  switch (f) {
    case FileFormat::StepAp242:
      return ExchangeFormat::StepAp242;
    case FileFormat::Iges:
      return ExchangeFormat::Iges;
    default:
      return ExchangeFormat::StepAp214;
  }
}
#else
bool is_step_or_iges(FileFormat f) {
  return f == FileFormat::StepAp214 || f == FileFormat::StepAp242 || f == FileFormat::Iges;
}

[[noreturn]] void no_occt(FileFormat f) {
  throw Error(
      Errc::Unsupported,
      std::string(file_format_name(f)) + " needs Open CASCADE, and this hula was built without it (HULA_WITH_OCCT=OFF)",
      {.field = "format"});
}
#endif

// The curve entity at `label`, or an error naming it.
Entity curve_entity(const Document& document, Label label, std::size_t i, std::string_view format) {
  const auto entity = document.find(label);
  if (!entity)
    throw Error(Errc::InvalidArgument, "label " + std::to_string(label.value) + " is not in the document",
                {.field = "labels", .index = i});
  if (entity->kind() != EntityKind::Curve)
    throw Error(
        Errc::InvalidArgument,
        "label " + std::to_string(label.value) + " is not a curve (" + std::string(format) + " carries curves only)",
        {.field = "labels", .index = i});
  return *entity;
}

// Reads `input` into `document`: its entities, in file order.
std::vector<Label> read_into(Document& document, const fs::path& input, FileFormat format, ConvertReport& report) {
  std::vector<Label> labels;
  switch (format) {
    case FileFormat::JsonFile: {
      const io::Json json = io::json::parse_json_text(io::read_text_file(input), input.string());
      document.transact("import", [&](Edit& e) { labels = import_json(e, json, input.string()); }).throw_if_failed();
      // A curve file has no name: the curves are named after the file, as a CAD system names a part.
      const std::string stem = input.stem().string();
      document
          .transact("name",
                    [&](Edit& e) {
                      std::size_t n = 0;
                      for (Label l : labels) {
                        const Entity entity = e.get(l);
                        if (entity.kind() != EntityKind::Curve || !entity.attributes().name.empty()) continue;
                        Attributes a = entity.attributes();
                        a.name = labels.size() == 1 ? stem : stem + "-" + std::to_string(++n);
                        e.set_attributes(l, a);
                      }
                    })
          .throw_if_failed();
      break;
    }
    case FileFormat::Dxf: {
      const io::DxfReadReport dxf = io::read_dxf_file(input);
      document.transact("import", [&](Edit& e) { labels = add_dxf_imported(e, dxf, input); }).throw_if_failed();
      report.warnings = dxf.warnings;
      break;
    }
    case FileFormat::Svg:
      throw Error(
          Errc::InvalidArgument,
          "cannot read '" + input.string() + "': SVG is written by convert, not read (json | step | iges | dxf)",
          {.field = "input"});
    default: {
#ifdef HULA_WITH_OCCT
      // STEP and IGES files are told apart by their extension (the helper reads them so); standard input
      // by --from.
      if (io::is_std_stream(input)) {
        const ImportReport imported = import_curves_from_stdin(exchange_format(format));
        document
            .transact("import", [&](Edit& e) { labels = add_imported(e, imported, input, exchange_format(format)); })
            .throw_if_failed();
        report.warnings = imported.warnings;
        break;
      }
      if ((exchange_format_for_path(input) == ExchangeFormat::Iges) != (format == FileFormat::Iges))
        throw Error(Errc::InvalidArgument,
                    "cannot read '" + input.string() + "' as " + std::string(file_format_name(format)) +
                        ": STEP and IGES files are read by their extension",
                    {.field = "format"});
      const ImportReport imported = import_curves(input);
      document.transact("import", [&](Edit& e) { labels = add_imported(e, imported, input); }).throw_if_failed();
      report.warnings = imported.warnings;
#else
      no_occt(format);
#endif
    }
  }
  return labels;
}

}  // namespace

std::string_view file_format_name(FileFormat format) noexcept {
  switch (format) {
    case FileFormat::JsonFile:
      return "json";
    case FileFormat::StepAp214:
      return "step-ap214";
    case FileFormat::StepAp242:
      return "step-ap242";
    case FileFormat::Iges:
      return "iges";
    case FileFormat::Dxf:
      return "dxf";
    case FileFormat::Svg:
      return "svg";
  }
  return "unknown";
}

FileFormat file_format_from_name(std::string_view name) {
  if (name == "json") return FileFormat::JsonFile;
  if (name == "step" || name == "step-ap214") return FileFormat::StepAp214;
  if (name == "step-ap242") return FileFormat::StepAp242;
  if (name == "iges") return FileFormat::Iges;
  if (name == "dxf") return FileFormat::Dxf;
  if (name == "svg") return FileFormat::Svg;
  throw Error(Errc::InvalidArgument,
              "unknown format '" + std::string(name) + "' (json | step | step-ap214 | step-ap242 | iges | dxf | svg)",
              {.field = "format"});
}

FileFormat file_format_for_path(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".json") return FileFormat::JsonFile;
  if (ext == ".step" || ext == ".stp") return FileFormat::StepAp214;
  if (ext == ".iges" || ext == ".igs") return FileFormat::Iges;
  if (ext == ".dxf") return FileFormat::Dxf;
  if (ext == ".svg") return FileFormat::Svg;
  throw Error(Errc::InvalidArgument,
              "cannot tell the format of '" + path.string() +
                  "' from its extension (.json, .step, .stp, .iges, .igs, .dxf, .svg); give --format",
              {.field = "path"});
}

namespace {

// The format of a file: the given one or its extension's; STEP and IGES refused without Open CASCADE.
FileFormat resolve_format(const std::optional<FileFormat>& given, const fs::path& path) {
  const FileFormat f = given ? *given : file_format_for_path(path);
#ifndef HULA_WITH_OCCT
  if (is_step_or_iges(f)) no_occt(f);
#endif
  return f;
}

// What a write needs that can be refused before anything is read: the SVG tolerance and the output path.
void check_output_options(const ConvertOptions& options, const fs::path& output) {
  if (!std::isfinite(options.svg_tolerance) || !(options.svg_tolerance > 0.0))
    throw Error(Errc::InvalidArgument,
                "tolerance = " + format_number(options.svg_tolerance) + " must be finite and > 0",
                {.field = "tolerance"});
  io::check_output_path(output, "--output");
}

}  // namespace

std::vector<Label> read_curve_file(Document& document, const fs::path& input, const ConvertOptions& options,
                                   ConvertReport& report) {
  report.input_format = resolve_format(options.input_format, input);
  return read_into(document, input, report.input_format, report);
}

void write_curve_file(const Document& document, std::span<const Label> all, const fs::path& output,
                      const ConvertOptions& options, ConvertReport& report) {
  report.output_format = resolve_format(options.output_format, output);
  check_output_options(options, output);
  std::vector<Label> labels;
  for (Label l : all)
    if (report.output_format == FileFormat::JsonFile || document.get(l).kind() == EntityKind::Curve)
      labels.push_back(l);
  report.skipped = all.size() - labels.size();
  if (labels.empty())
    throw Error(
        Errc::InvalidArgument,
        "no curve to write as " + std::string(file_format_name(report.output_format)) + " to '" + output.string() + "'",
        {.field = "input"});
  for (Label l : labels)
    if (document.get(l).kind() == EntityKind::Curve) {
      ++report.curves;
      report.max_deviation = std::max(report.max_deviation, document.get(l).curve().approximation_deviation());
    }
  switch (report.output_format) {
    case FileFormat::JsonFile:
      // The lossless path: law and natural-equation curves keep their construction data.
      report.max_deviation = 0.0;
      io::write_file_atomically(output, io::to_file_text(export_json(document, labels)), "--output");
      break;
    case FileFormat::Dxf:
      (void)export_dxf(document, labels, output);
      break;
    case FileFormat::Svg: {
      std::vector<io::SvgPathCurve> curves;
      for (std::size_t i = 0; i < labels.size(); ++i) {
        const Entity e = curve_entity(document, labels[i], i, "SVG");
        curves.push_back(
            {e.attributes().name, e.curve().nurbs(), e.attributes().colour, e.curve().approximation_deviation()});
      }
      const io::SvgPaths svg = io::svg_paths(curves, {options.svg_tolerance});
      report.max_deviation = svg.report.max_deviation;
      if (svg.report.projected)
        report.warnings.push_back("curves with z != 0 drawn as their projection on the XY plane");
      io::write_file_atomically(output, svg.text, "--output");
      break;
    }
    default: {
#ifdef HULA_WITH_OCCT
      report.max_deviation =
          export_entities(document, labels, output, exchange_format(report.output_format)).max_deviation;
#endif
    }
  }
}

ConvertReport convert_file(const fs::path& input, const fs::path& output, const ConvertOptions& options) {
  ConvertReport report;
  // Both formats, the tolerance and the output-path policy are checked before anything is read.
  report.input_format = resolve_format(options.input_format, input);
  report.output_format = resolve_format(options.output_format, output);
  check_output_options(options, output);
  Document document;
  const std::vector<Label> all = read_into(document, input, report.input_format, report);
  bool any_curve = report.output_format == FileFormat::JsonFile && !all.empty();
  for (Label l : all) any_curve = any_curve || document.get(l).kind() == EntityKind::Curve;
  if (!any_curve)
    throw Error(
        Errc::InvalidArgument,
        "'" + input.string() + "' holds no curve to write as " + std::string(file_format_name(report.output_format)),
        {.field = "input"});
  write_curve_file(document, all, output, options, report);
  return report;
}

std::vector<io::DxfCurve> dxf_items(const Document& document, std::span<const Label> labels) {
  if (labels.empty()) throw Error(Errc::InvalidArgument, "no labels to export", {.field = "labels"});
  std::vector<io::DxfCurve> out;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const Entity e = curve_entity(document, labels[i], i, "DXF");
    out.push_back({e.attributes().name, e.curve().nurbs(), e.attributes().layer, e.attributes().colour, {}});
  }
  return out;
}

namespace {
double largest_deviation(const Document& document, std::span<const Label> labels) {
  double deviation = 0.0;
  for (Label l : labels) deviation = std::max(deviation, document.get(l).curve().approximation_deviation());
  return deviation;
}
}  // namespace

DxfExport dxf_export(const Document& document, std::span<const Label> labels) {
  const auto items = dxf_items(document, labels);
  return {io::dxf_text(items), largest_deviation(document, labels)};
}

double export_dxf(const Document& document, std::span<const Label> labels, const fs::path& path) {
  const auto items = dxf_items(document, labels);
  io::write_dxf_file(path, items);
  return largest_deviation(document, labels);
}

std::vector<Label> add_dxf_imported(Edit& edit, const io::DxfReadReport& report, const fs::path& source) {
  std::vector<Label> out;
  for (const auto& c : report.curves) {
    Provenance p;
    p.operation = "import:dxf";
    p.tool_version = HULA_VERSION;
    p.details["file"] = source.string();
    p.details["source"] = c.source;
    Attributes attributes;
    attributes.name = c.name;
    if (!c.colour.empty()) attributes.colour = c.colour;
    attributes.layer = c.layer;
    out.push_back(edit.add_curve(curve::Curve(c.curve), attributes, p));
  }
  return out;
}

}  // namespace hula::oli
