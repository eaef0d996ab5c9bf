// SPDX-License-Identifier: MIT
// JSON curve files (DESIGN.md io, thesis 10.2): reading and writing the three
// kinds of curve file the CLI and, later, Oli exchange. The format is
// documented in docs/formats.md; in short:
//
//   {"kind": "nurbs", "degree": 3, "knots": [...full Piegl–Tiller vector...],
//    "control_points": [[x, y, z] or [x, y], ...], "weights": [...] or null}
//   {"kind": "bezier", "control_points": [...], "weights": [...] or null}
//   {"kind": "interpolated", "points": [...],
//    "parameterisation": "uniform" | "chord" | "centripetal",
//    "parameters": [...]?, "knots": [...]?, "start": END, "end": END}
//      END = "natural" | "bessel" | "not-a-knot" | "occt" | {"tangent": [x, y, z]}
//   {"kind": "law", "expression": "vec(2*cos(t), 2*sin(t), 0.5*t)", "parameter": "t",
//    "domain": [t0, t1]}   (a 2- or 3-vector law; grammar in docs/formats.md)
//
// 2-D points ([x, y]) give a 2-D curve (dimension 2) and are written back as
// [x, y]. Members not listed here are ignored, so files written by a newer
// version that adds members still load (forward compatibility); a repeated
// member keeps its last value (nlohmann::json behaviour). Doubles round-trip
// bit-exactly: the writer prints the shortest decimal that reads back to the
// same double.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/law/expr.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::io {

/// The JSON value type used by the io module (member order preserved on output).
using Json = nlohmann::ordered_json;

/// The "kind" member of a curve file.
enum class CurveKind {
  Nurbs,         ///< "nurbs": degree, full knot vector, control points, optional weights
  Bezier,        ///< "bezier": control points (degree = count - 1), optional weights
  Interpolated,  ///< "interpolated": data points and end conditions, resolved by interpolate_cubic
  Law,           ///< "law": a vector law (expression text) of one parameter on a domain
};

/// Tolerance of the NURBS that stands in for a law curve (CurveFile::curve) in tools that need one.
inline constexpr double kLawCurveTolerance = 1e-6;

/// A "law" curve file after reading: the expression, compiled in its own context.
struct LawCurve {
  /// The expression as stored in the file.
  std::string expression;
  /// The parameter name ("parameter", default "t").
  std::string parameter = "t";
  /// The domain [start, end], start < end.
  nurbs::Interval domain{};
  /// The parsed law (2- or 3-vector), owned by its context.
  law::Law law{};
  /// max |law(t) − curve(t)| of the stand-in NURBS (≤ kLawCurveTolerance), by dense sampling.
  double approximation_deviation = 0.0;
};

/// The file name of a kind: "nurbs", "bezier" or "interpolated".
[[nodiscard]] std::string_view curve_kind_name(CurveKind kind) noexcept;

/// The inputs of an "interpolated" curve file, as stored in the file.
struct InterpolationInputs {
  /// N ≥ 2 data points in model units (z = 0 when dimension is 2).
  std::vector<Vec3> points;
  /// 2 when the points were written as [x, y], else 3.
  int dimension = 3;
  /// Parameter rule used when `parameters` is empty. Default chord length.
  nurbs::Parameterisation parameterisation = nurbs::Parameterisation::ChordLength;
  /// Given data parameters (the file's "parameters" or "knots"), or empty.
  std::vector<double> parameters;
  /// End conditions. Default natural.
  nurbs::EndCondition start = nurbs::EndCondition::natural();
  nurbs::EndCondition end = nurbs::EndCondition::natural();

  /// The options of interpolate_cubic that these inputs describe.
  [[nodiscard]] nurbs::InterpolationOptions options() const;
};

/// Resolves interpolation inputs to the NURBS curve (interpolate_cubic).
/// @param inputs the points, parameters and end conditions
/// @param parameters_field the name under which the given parameters reached
///   the user ("parameters", or "knots" when they came from a "knots" member or
///   a --knots option): errors about them are reported under this name
/// @throws hula::Error from interpolate_cubic (TooFewPoints, CoincidentPoints,
///   InvalidArgument for bad parameters, NonFiniteInput, ...)
[[nodiscard]] nurbs::NurbsCurve resolve(const InterpolationInputs& inputs,
                                        std::string_view parameters_field = "parameters");

/// A curve file after reading: the resolved curve and what the file held.
struct CurveFile {
  /// The curve the file describes (interpolated kinds already resolved).
  nurbs::NurbsCurve curve;
  /// The file's "kind".
  CurveKind kind = CurveKind::Nurbs;
  /// For CurveKind::Interpolated, the inputs as stored; empty otherwise.
  std::optional<InterpolationInputs> inputs;
  /// For CurveKind::Law, the law (exact: evaluate it rather than `curve` when possible);
  /// `curve` is then law::to_nurbs of it within kLawCurveTolerance.
  std::optional<LawCurve> law;
};

/// Parses an END value: "natural", "bessel", "not-a-knot", "occt" or {"tangent": [x, y(, z)]}.
/// @param value the JSON value
/// @param field the member name used in messages ("start" or "end")
/// @throws hula::Error(Errc::ParseError) naming the member and the value
[[nodiscard]] nurbs::EndCondition end_condition_from_json(const Json& value, std::string_view field);
/// The JSON form of an end condition (a string, or {"tangent": [x, y, z]}; [x, y] when dimension is 2).
[[nodiscard]] Json end_condition_to_json(const nurbs::EndCondition& end, int dimension = 3);
/// Parses "uniform", "chord" or "centripetal".
/// @throws hula::Error(Errc::ParseError) naming `field` and the value
[[nodiscard]] nurbs::Parameterisation parameterisation_from_name(std::string_view name,
                                                                 std::string_view field = "parameterisation");
/// "uniform", "chord" or "centripetal".
[[nodiscard]] std::string_view parameterisation_name(nurbs::Parameterisation rule) noexcept;

/// Builds a curve from a parsed JSON document.
/// @param document the parsed file
/// @returns the resolved curve with its kind and, for interpolated files, the inputs
/// @throws hula::Error(Errc::ParseError) if the document is not an object, "kind" is
///   missing or unknown (names the kind), a member is missing, has the wrong type
///   (names the JSON path, e.g. `control_points[3][1]`, and the value), points mix
///   2 and 3 components (names the index), an END or parameterisation name is
///   unknown, or "parameters" and "knots" are both given and differ
/// @throws hula::Error(Errc::NonFiniteInput) if a number literal overflows a double
/// @throws hula::Error(Errc::TooFewPoints / InvalidDegree) if a "bezier" file has fewer
///   than 2 or more than kMaxDegree + 1 control points
/// @throws hula::Error from the kernel (InvalidKnots, InvalidDegree, InvalidWeight, ...)
///   with its own field / index (e.g. field "knots", the index of the decreasing knot)
/// @throws for "law" files: hula::Error(Errc::ParseError) with field "expression", line and
///   column for a bad expression (or a scalar law), field "domain" for a domain that is not two
///   finite numbers start < end; hula::Error(Errc::NumericalFailure) naming the parameter value
///   where the law is undefined on its domain
[[nodiscard]] CurveFile curve_from_json(const Json& document);
/// Parses curve-file text; as curve_from_json, plus ParseError with line/column for bad JSON.
[[nodiscard]] CurveFile parse_curve_json(std::string_view text);
/// Reads a curve file from disk.
/// @throws hula::Error(Errc::IoError) naming the path, or as parse_curve_json
[[nodiscard]] CurveFile read_curve_file(const std::filesystem::path& path);

/// The "nurbs" kind document of a curve (2-D curves write [x, y] points;
/// weights are null for a non-rational curve).
[[nodiscard]] Json curve_to_json(const nurbs::NurbsCurve& curve);
/// The "interpolated" kind document of interpolation inputs ("parameters"
/// written only when given).
[[nodiscard]] Json interpolated_to_json(const InterpolationInputs& inputs);
/// The "law" kind document of a law curve: kind, expression, parameter, domain.
[[nodiscard]] Json law_to_json(const LawCurve& curve);
/// Serialises a document as the files are written (format_json: 2-space indentation, arrays of
/// numbers on one line, final newline).
[[nodiscard]] std::string to_file_text(const Json& document);
/// Writes a curve as a "nurbs" file, atomically.
/// @throws hula::Error(Errc::IoError) naming the path
void write_curve_file(const std::filesystem::path& path, const nurbs::NurbsCurve& curve);
/// Writes interpolation inputs as an "interpolated" file, atomically.
/// @throws hula::Error(Errc::IoError) naming the path
void write_interpolated_file(const std::filesystem::path& path, const InterpolationInputs& inputs);

}  // namespace hula::io
