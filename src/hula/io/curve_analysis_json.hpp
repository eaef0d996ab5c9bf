// SPDX-License-Identifier: MIT
// The one codec of a curve's analysis (diffgeom::analyse_curve): the request
// every door reads (POST …/analysis, the change set's "analysis", the CLI's
// options gathered into the same value) and the answer every door writes
// (`hula analyse`, the HTTP body; Python converts the same value to arrays).
// One set of member names (docs/formats.md, "Curve analysis"):
//   {"t", "s"?, "points", "frames": {"T", "N", "B"}, "curvature", "torsion",
//    "curvature_derivative", "speed", "bishop"?: {"U", "V"},
//    "fins": [{"kind", "scale", "t", "base", "tip"}],
//    "planarity": {"planar", "normal", "max_deviation", "tolerance"},
//    "features"?: {"inflections": [{"t", "point"}],
//                  "curvature_extrema": [{"kind", "t", "point", "curvature"}],
//                  "torsion_extrema": [{"kind", "t", "point", "torsion"}],
//                  "knots": [{"t", "multiplicity", "parametric", "geometric",
//                             "tangent_angle", "curvature_left", "curvature_right", "left", "right"}],
//                  "curvature_monotonicity": {"monotone", "pieces", "violations"},
//                  "maximum_curvature": {"value", "t"}}}
// Columns hold one entry per sample; undefined values are null. Every double
// reads back bit for bit.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "hula/diffgeom/analysis.hpp"
#include "hula/io/json_read.hpp"
#include "hula/io/json_text.hpp"

namespace hula::io {

/// Reads an analysis request {"samples"?, "at"?, "by"?: "parameter"|"arclength", "arc_lengths"?,
/// "bishop"?, "fins"?: [kind...], "scale"?, "fin_density"?, "features"?}; absent members keep
/// `defaults`.
/// @throws hula::Error(Errc::ParseError) for an unknown or mistyped member, (Errc::InvalidOption) for a
///   value out of range or an unknown fin kind or abscissa, naming the member (and the index)
[[nodiscard]] diffgeom::AnalysisOptions analysis_options_from_json(const json::Json& body,
                                                                   const diffgeom::AnalysisOptions& defaults);

/// The members of an analysis (the file comment's shape) written into an open object of `w`.
void write_curve_analysis_members(JsonText& w, const diffgeom::CurveAnalysis& analysis);

/// The analysis as JSON text: compact (HTTP) or in format_json's layout (the CLI, final newline);
/// with "revision" last when given.
[[nodiscard]] std::string curve_analysis_json(const diffgeom::CurveAnalysis& analysis, bool pretty,
                                              std::optional<std::uint64_t> revision = std::nullopt);

/// The defaults of an HTTP analysis request (docs/server.md): 100 samples by parameter, features on,
/// no fins (the automatic scale when fins are asked without "scale").
[[nodiscard]] diffgeom::AnalysisOptions analysis_request_defaults();

/// diffgeom::analyse_curve of `curve` written by curve_analysis_json: what `hula analyse` prints and
/// POST .../analysis answers for the same options.
/// @throws hula::Error as diffgeom::analyse_curve
[[nodiscard]] std::string analyse_curve_json(const curve::Curve& curve, const diffgeom::AnalysisOptions& options,
                                             bool pretty, std::optional<std::uint64_t> revision = std::nullopt);

/// The continuity at a knot: {"t", "multiplicity", "parametric": k of Ck (null below C0), "geometric": k of
/// Gk, "tangent_angle", "curvature_left", "curvature_right", "left": the four one-sided derivatives C to
/// C''' from below, "right": from above} (thesis Table 3; non-finite values null).
[[nodiscard]] json::Json continuity_to_json(const diffgeom::Continuity& continuity);
/// {"planar", "normal" ([x, y, z] or null), "max_deviation", "tolerance"}.
[[nodiscard]] json::Json planarity_to_json(const diffgeom::Planarity& planarity);
/// {"value", "t"} (null where the curvature is nowhere defined).
[[nodiscard]] json::Json maximum_curvature_to_json(const diffgeom::MaximumCurvature& maximum);

/// "maximum" or "minimum": the kind of an extremum in the feature lists.
[[nodiscard]] std::string_view extremum_kind_name(diffgeom::FeatureKind kind) noexcept;

}  // namespace hula::io
