// SPDX-License-Identifier: MIT
// JSON curve files (DESIGN.md io, thesis 10.2): the codec of the curve value
// type (curve::Curve), all six kinds. The format is documented in
// docs/formats.md; in short, every file written starts with
// "format": "hula-curve", "version": 1, then
//
//   {"kind": "nurbs", "degree": 3, "knots": [...full Piegl–Tiller vector...],
//    "control_points": [[x, y, z] or [x, y], ...], "weights": [...] or null}
//   {"kind": "bezier", "control_points": [...], "weights": [...] or null}
//   {"kind": "interpolated", "points": [...],
//    "parameterisation": "uniform" | "chord" | "centripetal" | "foley",
//    "parameters": [...]?, "knots": [...]?, "start": END, "end": END}
//      END = "natural" | "bessel" | "not-a-knot" | "occt" | {"tangent": [x, y, z]}
//   {"kind": "hermite", "points": [...], "tangents": [...], "second_derivatives": [...]?,
//    "parameters": [...]?}
//   {"kind": "law", "expression": "vec(2*cos(t), 2*sin(t), 0.5*t)", "parameter": "t",
//    "domain": [t0, t1]}   (a 2- or 3-vector law; grammar in docs/formats.md)
//   {"kind": "natural", "curvature": "0.8", "torsion": "0.4", "parameter": "s", "length": L,
//    "start": {"point": [...], "tangent": [...], "normal": [...]}, "tolerance": 1e-10?}
//      (stored by its laws and evaluated exactly: κ, τ from the laws, position and frame
//      integrated to "tolerance", default curve::kNaturalTolerance for files without it)
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
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/curve/curve.hpp"
#include "hula/nurbs/interpolate.hpp"

namespace hula::io {

/// The JSON value type used by the io module (member order preserved on output).
using Json = nlohmann::ordered_json;

/// The "format" member of every curve file written, and the version written and understood.
/// A file without "format"/"version" reads as version 1 (files written before the tag existed).
inline constexpr std::string_view kCurveFormat = "hula-curve";
inline constexpr int kCurveFormatVersion = 1;

/// Resolves interpolation data to a curve (curve::Curve::interpolated), naming the given
/// parameters as the user wrote them.
/// @param data the points, parameters and end conditions
/// @param parameters_field the name under which the given parameters reached the user
///   ("parameters", or "knots" when they came from a "knots" member or a --knots option):
///   errors about them are reported under this name
/// @throws hula::Error from interpolate_cubic (TooFewPoints, CoincidentPoints,
///   InvalidArgument for bad parameters, NonFiniteInput, ...)
[[nodiscard]] curve::Curve interpolated_curve(curve::InterpolatedData data,
                                              std::string_view parameters_field = "parameters");

/// Parses an END value: "natural", "bessel", "not-a-knot", "occt" or {"tangent": [x, y(, z)]}.
/// @param value the JSON value
/// @param field the member name used in messages ("start" or "end")
/// @throws hula::Error(Errc::ParseError) naming the member and the value
[[nodiscard]] nurbs::EndCondition end_condition_from_json(const Json& value, std::string_view field);
/// The JSON form of an end condition (a string, or {"tangent": [x, y, z]}; [x, y] when dimension is 2).
[[nodiscard]] Json end_condition_to_json(const nurbs::EndCondition& end, int dimension = 3);
/// Parses "uniform", "chord", "centripetal" or "foley".
/// @throws hula::Error(Errc::ParseError) naming `field` and the value
[[nodiscard]] nurbs::Parameterisation parameterisation_from_name(std::string_view name,
                                                                 std::string_view field = "parameterisation");
/// "uniform", "chord", "centripetal" or "foley".
[[nodiscard]] std::string_view parameterisation_name(nurbs::Parameterisation rule) noexcept;

/// Builds a curve from a parsed JSON document (any of the six kinds, docs/formats.md).
/// @param document the parsed file
/// @returns the curve with its construction data
/// @throws hula::Error(Errc::ParseError) if the document is not an object, "format" is present and
///   not "hula-curve", "version" is present and not an integer in [1, kCurveFormatVersion], "kind"
///   is missing or unknown (names the kind), a member is missing, has the wrong type (names the
///   JSON path, e.g. `control_points[3][1]`, and the value), points mix 2 and 3 components (names
///   the index), an END or parameterisation name is unknown, or "parameters" and "knots" are both
///   given and differ
/// @throws hula::Error(Errc::NonFiniteInput) if a number literal overflows a double
/// @throws hula::Error from the curve factories (TooFewPoints, InvalidDegree, InvalidKnots,
///   InvalidWeight, ...) with their own field / index (e.g. field "knots", the index of the
///   decreasing knot)
/// @throws for "law" files: hula::Error(Errc::ParseError) with field "expression", line and
///   column for a bad expression (or a scalar law), field "domain" for a domain that is not two
///   finite numbers start < end; hula::Error(Errc::InvalidArgument) naming the parameter value
///   where the law is undefined on its domain
/// @throws for "natural" files: as intrinsic::natural_curve at curve::kApproximationTolerance
[[nodiscard]] curve::Curve curve_from_json(const Json& document);
/// Parses curve-file text; as curve_from_json, plus ParseError with line/column for bad JSON.
[[nodiscard]] curve::Curve parse_curve_json(std::string_view text);
/// Reads a curve file from disk (at most kMaxGeometryInputBytes, the limit write_curve_file keeps to).
/// @throws hula::Error(Errc::IoError) naming the path, or as parse_curve_json
[[nodiscard]] curve::Curve read_curve_file(const std::filesystem::path& path);

/// The document of a curve: "format", "version", "kind", then the construction data of its kind
/// (2-D curves write [x, y] points; weights are null for a non-rational NURBS). Doubles are
/// written so that curve_from_json(curve_to_json(c)) == c bit for bit.
[[nodiscard]] Json curve_to_json(const curve::Curve& curve);

/// A point as [x, y] (dimension 2) or [x, y, z] (otherwise), as the curve files write them.
[[nodiscard]] Json point_to_json(const Vec3& p, int dimension);
/// Points as an array of point_to_json.
[[nodiscard]] Json points_to_json(std::span<const Vec3> points, int dimension);
/// Serialises a document as the files are written (format_json: 2-space indentation, arrays of
/// numbers on one line, final newline).
[[nodiscard]] std::string to_file_text(const Json& document);
/// The text of a curve file: format_json(curve_to_json(curve)), byte for byte, written without
/// building the JSON value.
[[nodiscard]] std::string curve_file_text(const curve::Curve& curve);
/// Writes a curve file (curve_file_text), atomically, streamed in bounded memory.
/// @throws hula::Error(Errc::InvalidArgument) naming the path when the text would be longer than
///   kMaxGeometryInputBytes (read_curve_file could not read it back); the target is left as it was
/// @throws hula::Error(Errc::IoError) naming the path
void write_curve_file(const std::filesystem::path& path, const curve::Curve& curve);

}  // namespace hula::io
