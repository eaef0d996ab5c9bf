// SPDX-License-Identifier: MIT
// One-step conversion of curve files between the formats the document
// exchanges: JSON (a curve file or a hula-document), STEP (AP214, AP242),
// IGES, DXF and SVG (written only). The input is read into a fresh in-memory
// document (names, colours and layers as the file gives them) and its curve
// entities are written out, so a conversion is exactly an import followed by an
// export: STEP and IGES through the isolated Open CASCADE helper
// (exchange/exchange.hpp), DXF through io/dxf_file.hpp, SVG as Bézier paths
// (io/svg_paths.hpp). The output is written atomically or not at all.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hula/io/dxf_file.hpp"
#include "hula/io/svg_paths.hpp"
#include "hula/oli/document.hpp"
#ifdef HULA_WITH_OCCT
#include "hula/oli/exchange/exchange.hpp"
#endif

namespace hula::oli {

/// A file format of `convert`.
enum class FileFormat {
  JsonFile,   ///< a curve file (one curve) or a hula-document (several, with attributes); ".json"
  StepAp214,  ///< ".step", ".stp"
  StepAp242,  ///< chosen by name only
  Iges,       ///< ".iges", ".igs"
  Dxf,        ///< ".dxf"
  Svg,        ///< ".svg", written only
};

/// "json", "step-ap214", "step-ap242", "iges", "dxf" or "svg".
[[nodiscard]] std::string_view file_format_name(FileFormat format) noexcept;
/// Parses "json", "step" (= "step-ap214"), "step-ap214", "step-ap242", "iges", "dxf", "svg".
/// @throws hula::Error(Errc::InvalidArgument) with field "format" naming the value and the choices
[[nodiscard]] FileFormat file_format_from_name(std::string_view name);
/// The format of a file from its extension (case-insensitive).
/// @throws hula::Error(Errc::InvalidArgument) with field "path" naming the file and the extensions known
[[nodiscard]] FileFormat file_format_for_path(const std::filesystem::path& path);

/// Options of convert_file.
struct ConvertOptions {
  /// The input's format; nullopt: from its extension.
  std::optional<FileFormat> input_format{};
  /// The output's format; nullopt: from its extension.
  std::optional<FileFormat> output_format{};
  /// SVG only: largest deviation of the cubic pieces of curves with no exact cubic form (model units).
  double svg_tolerance = io::SvgPathOptions{}.tolerance;
};

/// What convert_file did.
struct ConvertReport {
  FileFormat input_format{};
  FileFormat output_format{};
  std::size_t curves = 0;  ///< curves written
  /// Entities of the input that the output format cannot carry (point sets and studies, for every format
  /// but JSON), left out.
  std::size_t skipped = 0;
  /// The largest distance between a written curve and the curve it stands for (NURBS approximations of
  /// law and natural-equation curves; SVG pieces of curves with no exact cubic form); 0 when exact.
  double max_deviation = 0.0;
  /// What the reader reported and did not refuse (STEP/IGES presentation problems, DXF entities skipped).
  std::vector<std::string> warnings{};
};

/// Reads `input` and writes its curves to `output` in another (or the same) format.
/// @param output the file written (replaced atomically), or `-` for standard output
/// @throws hula::Error(Errc::InvalidArgument) for an unknown extension or format name, or SVG as input
/// @throws hula::Error(Errc::Unsupported) for STEP/IGES in a build without Open CASCADE
/// @throws the reader's errors (ParseError, IoError naming the input, …) and the writer's (IoError naming
///   the output, …); nothing is written then
ConvertReport convert_file(const std::filesystem::path& input, const std::filesystem::path& output,
                           const ConvertOptions& options = {});

/// convert_file's reading half: the entities of `input` added to `document` (names, colours and layers as
/// the file gives them; a curve file's curves named after the file), in file order; sets report.input_format
/// and report.warnings. hulahoops.read uses it.
/// @throws as convert_file for the input
std::vector<Label> read_curve_file(Document& document, const std::filesystem::path& input,
                                   const ConvertOptions& options, ConvertReport& report);

/// convert_file's writing half: the entities of `labels` written to `output` (JSON: every entity; the other
/// formats: the curves, the rest counted in report.skipped); sets report.output_format, curves, skipped,
/// max_deviation and warnings. hulahoops.write uses it.
/// @throws hula::Error(Errc::InvalidArgument) when no curve is left to write; as convert_file for the output
void write_curve_file(const Document& document, std::span<const Label> labels, const std::filesystem::path& output,
                      const ConvertOptions& options, ConvertReport& report);

/// The curves of `labels` as DXF SPLINE items: each curve's NURBS (a law or natural-equation curve's
/// NURBS approximation) with the entity's name, colour and layer.
/// @throws hula::Error(Errc::InvalidArgument) naming a label that is missing or not a curve, or for no labels
[[nodiscard]] std::vector<io::DxfCurve> dxf_items(const Document& document, std::span<const Label> labels);

/// The curves of `labels` as DXF text (dxf_items, then io::dxf_text) and the largest NURBS
/// approximation deviation among them (0 when all are NURBS): what the server's export returns.
struct DxfExport {
  std::string text;
  double max_deviation = 0.0;
};
[[nodiscard]] DxfExport dxf_export(const Document& document, std::span<const Label> labels);

/// Writes the curves of `labels` to a DXF file (dxf_items, then io::write_dxf_file).
/// @returns the largest NURBS approximation deviation of the curves written (0 when all are NURBS)
[[nodiscard]] double export_dxf(const Document& document, std::span<const Label> labels,
                                const std::filesystem::path& path);

/// Adds the SPLINE curves of a DXF file as NURBS curve entities with their names, colours and layers
/// and the provenance "import:dxf" (details: file, source). Call inside a transaction.
/// @returns the new labels in file order
std::vector<Label> add_dxf_imported(Edit& edit, const io::DxfReadReport& report, const std::filesystem::path& source);

}  // namespace hula::oli
