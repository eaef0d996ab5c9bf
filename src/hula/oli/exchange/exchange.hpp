// SPDX-License-Identifier: MIT
// STEP (AP214, AP242) and IGES 5.3 exchange of curves through Open CASCADE,
// run in a separate process (thesis 9.1.2: the modeller's
// readers are someone else's code). OCCT's readers crash on some malformed
// files, so the caller never loads them: export_curves and import_curves write
// a JSON request to a private temporary directory, spawn the `hula-exchange`
// helper with a time limit and an address-space limit (RLIMIT_AS), and read
// its JSON answer. A crash or a hang becomes hula::Error(Errc::HelperFailure)
// naming the file, an allocation failure in the helper ExchangeOutOfMemory (a
// std::bad_alloc naming the file, like memory running out in the caller: exit
// 6 in the CLI, 503 on the server); nothing in the caller's
// process has changed. Curves cross the boundary in the curve-file JSON format
// (io/json_curve.hpp), doubles bit-exact.
//
// Export writes B-spline curves (IGES entity 126, STEP
// B_SPLINE_CURVE_WITH_KNOTS, rational ones as the complex rational entity)
// with their names (STEP: the curve entity's name; IGES: the 8-character
// label and a Name property, 406 form 15). Curves that are NURBS
// approximations of law or natural-equation curves carry their maximum
// deviation; the largest is written into the file's metadata: STEP's
// FILE_DESCRIPTION and the model's uncertainty, IGES's global-section
// resolution (field 19) and its start section.
//
// Import reads the edges of every shape Open CASCADE's reader transfers (its
// roots: STEP shapes and curve sets, IGES independent curves and surfaces)
// whose geometry is a B-spline, Bézier, line, circle, ellipse, parabola or
// hyperbola, bounded by the edge, as NURBS (conics exactly, as rational
// quadratics), with the name the file gives the curve entity. What the reader
// could not read besides (presentation entities, unresolved references) is
// reported as warnings, not refused.
#pragma once

#include <cstddef>
#include <filesystem>
#include <new>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hula/curve/curve.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::oli {

/// A file format of the exchange.
enum class ExchangeFormat {
  StepAp214,  ///< ISO 10303-21 file, AP214 (AUTOMOTIVE_DESIGN) schema; ".step" / ".stp"
  StepAp242,  ///< ISO 10303-21 file, AP242 schema
  Iges,       ///< IGES 5.3; ".iges" / ".igs"
};

/// "step-ap214", "step-ap242" or "iges".
[[nodiscard]] std::string_view exchange_format_name(ExchangeFormat format) noexcept;
/// Parses a format name: "step" (= "step-ap214"), "step-ap214", "step-ap242", "iges".
/// @throws hula::Error(Errc::InvalidArgument) with field "format" naming the value and the choices
[[nodiscard]] ExchangeFormat exchange_format_from_name(std::string_view name);
/// The format of a file from its extension (case-insensitive): .step/.stp → AP214 (a reader
/// accepts any STEP schema), .iges/.igs → IGES.
/// @throws hula::Error(Errc::InvalidArgument) with field "path" naming the file and the extensions
[[nodiscard]] ExchangeFormat exchange_format_for_path(const std::filesystem::path& path);

/// One curve to export.
struct ExportCurve {
  /// The name written into the file (may be empty).
  std::string name;
  /// The curve written (for a law or natural-equation curve, its NURBS approximation).
  nurbs::NurbsCurve curve;
  /// Maximum distance of `curve` from the curve it stands for, in model units; 0 when `curve` is
  /// the curve itself.
  double deviation = 0.0;
  /// The curve's colour "#rrggbb", written as its XCAF colour (STEP styled item, IGES colour
  /// definition), or empty for none.
  std::string colour{};
  /// The curve's layer, written as its XCAF layer (STEP presentation layer; IGES level, numbered in order
  /// of first use, with the name in a Level Function property), or empty.
  std::string layer{};
};

/// The export item of a curve value: its NURBS (for a law or natural-equation curve, the NURBS
/// approximation) with the approximation's maximum deviation (curve::Curve::approximation_deviation).
[[nodiscard]] ExportCurve export_curve(std::string name, const curve::Curve& curve);

/// Limits and location of the helper process.
struct ExchangeOptions {
  /// The helper executable. Empty: default_exchange_helper().
  std::filesystem::path helper{};
  /// Wall-clock limit in seconds, after which the helper is killed (SIGKILL). Default 60; > 0.
  double time_limit = 60.0;
  /// Address-space limit of the helper (RLIMIT_AS) in bytes. Default 4 GiB; ≥ 256 MiB, since
  /// Open CASCADE's libraries alone map about 150 MiB.
  std::size_t memory_limit = std::size_t{4} << 30;
  /// @throws hula::Error(Errc::InvalidOption) naming the bad field
  void validate() const;
};

/// What an export wrote.
struct ExportReport {
  std::filesystem::path path;  ///< the file written
  ExchangeFormat format{};     ///< its format
  std::size_t curves = 0;      ///< number of curves written
  double max_deviation = 0.0;  ///< the largest ExportCurve::deviation, written into the metadata
};

/// One curve read from a file.
struct ImportedCurve {
  /// The name the file gives the curve (STEP entity name, IGES name property or label), or empty.
  std::string name;
  /// Where it came from: "#12" (STEP entity), "DE 7" (IGES directory entry).
  std::string source;
  /// The file's geometry: "b-spline", "bezier", "line", "circle", "ellipse", "parabola", "hyperbola".
  std::string type;
  /// The curve as NURBS on the edge's bounds (3-D).
  nurbs::NurbsCurve curve;
  /// The colour the file gives the curve (XCAF), "#rrggbb", or empty.
  std::string colour{};
  /// The layer the file puts the curve on (STEP: XCAF; IGES: the Level Function's name, else the level
  /// number), or empty.
  std::string layer{};
};

/// What an import read.
struct ImportReport {
  std::vector<ImportedCurve> curves;  ///< one per distinct edge Open CASCADE's reader transferred
  std::size_t skipped = 0;            ///< edges of other geometry (offset curves, …), not imported
  /// What the reader could not read while the geometry came in: presentation and schema problems
  /// ("entity #5: Parameter n0.2 (curve_font) not an Entity", colours, unresolved references,
  /// unknown entities), one line each, at most 20 then a count. Never a refusal.
  std::vector<std::string> warnings;
};

/// The exchange helper ran out of memory (a std::bad_alloc in the helper, under its address-space
/// limit): a std::bad_alloc, so every boundary treats it as memory running out, whose what() names
/// the file and the limit.
class ExchangeOutOfMemory : public std::bad_alloc {
 public:
  explicit ExchangeOutOfMemory(std::string message) : message_(std::move(message)) {}
  [[nodiscard]] const char* what() const noexcept override { return message_.c_str(); }

 private:
  std::string message_;
};

/// The helper used when ExchangeOptions::helper is empty: $HULA_EXCHANGE_HELPER if set, else
/// `hula-exchange` next to the binary this code was loaded from (the Python extension module of a
/// wheel, which ships it in the package) if it exists, else next to the running executable if it
/// exists, else the build tree's helper.
[[nodiscard]] std::filesystem::path default_exchange_helper();

/// Writes curves to a STEP or IGES file (replaced atomically: the helper writes a temporary file
/// that is renamed over `path` only when complete), or to standard output for `-`. The output-path
/// policy of every writer (io::check_output_path) is checked before the helper starts: a symbolic
/// link (dangling or not), FIFO, device or directory at `path` is refused, never replaced.
/// @param path the output file, or `-`
/// @param curves ≥ 1 curves
/// @throws hula::Error(Errc::InvalidArgument) if curves is empty or a deviation is negative or not finite
/// @throws hula::Error(Errc::IoError) naming the path if it cannot be written
/// @throws hula::Error(Errc::Unsupported) if a curve's degree exceeds Open CASCADE's limit (25)
/// @throws hula::Error(Errc::HelperFailure) naming the path if the helper crashed or hung
/// @throws ExchangeOutOfMemory naming the path if the helper ran out of memory
[[nodiscard]] ExportReport export_curves(const std::filesystem::path& path, std::span<const ExportCurve> curves,
                                         ExchangeFormat format, const ExchangeOptions& options = {});

/// Reads the curves of a STEP or IGES file (format from the extension).
/// @throws hula::Error(Errc::IoError) naming the path if it cannot be read
/// @throws hula::Error(Errc::ParseError) naming the path if it is not a STEP/IGES file, the reader
///   refuses it, or it holds no importable curve
/// @throws hula::Error(Errc::HelperFailure) naming the path if the reader crashed or hung
/// @throws ExchangeOutOfMemory naming the path if the reader ran out of memory
[[nodiscard]] ImportReport import_curves(const std::filesystem::path& path, const ExchangeOptions& options = {});

/// Reads the curves of a STEP or IGES file given on standard input (`hula convert - --from step`): the
/// bytes (at most io::kMaxGeometryInputBytes) are copied into the exchange's private scratch folder, which
/// the reader reads and which is removed after, whatever happens; messages name `-`.
/// @throws as import_curves, naming `-`
[[nodiscard]] ImportReport import_curves_from_stdin(ExchangeFormat format, const ExchangeOptions& options = {});

}  // namespace hula::oli
