// SPDX-License-Identifier: MIT
// What a viewport draws for one curve, computed without changing anything
// (POST /api/documents/{name}/entities/{label}/analysis): samples by
// parameter or by arc length with points, Frenet frames, κ, τ and speed
// (diffgeom::frenet of the curve's NURBS), fin combs (diffgeom::fins,
// equally spaced in the parameter, exactly from the law of a law curve;
// "combescure" is the Combescure compound of thesis 8.3/8.5), and the
// features: inflections, curvature extrema and the continuity at every
// interior knot (diffgeom). Undefined values are null.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hula/curve/curve.hpp"
#include "hula/diffgeom/fins.hpp"
#include "hula/server/http.hpp"

namespace hula::server {

/// How to sample.
enum class SampleBy { Parameter, ArcLength };

struct AnalysisRequest {
  /// Number of samples, ends included, in [2, 100000]. Default 100.
  int samples = 100;
  /// Equal steps in the parameter or in arc length. Default parameter.
  SampleBy by = SampleBy::Parameter;
  /// Fin combs to draw ("curvature", "torsion", "normal", "binormal", "bishop-u", "bishop-v",
  /// "combescure": Q − P = scale · (τ/κ T + B), null at planar points), each with `samples` fins.
  /// Default none.
  std::vector<diffgeom::FinKind> fins{};
  /// Fin scale (model units per unit of the quantity; the constant C of the Combescure fin), finite.
  /// Default 1.
  double scale = 1.0;
  /// Include features (inflections, curvature extrema, knot continuity). Default true.
  bool features = true;
};

/// Reads {"samples"?, "by"?: "parameter"|"arclength", "fins"?: [...], "scale"?, "features"?}.
/// @throws hula::Error(Errc::ParseError) for an unknown or mistyped member, (Errc::InvalidOption) for a
///   value out of range, naming the member
[[nodiscard]] AnalysisRequest analysis_request_from_json(const Json& body);

/// The response body (compact JSON text): columns, one entry per sample: {"t", "points", "frames":
/// {"T", "N", "B"}, "curvature", "torsion", "speed"}, plus "fins": [{"kind", "t", "base", "tip"}] and,
/// when asked, "features": {"inflections": [{"t", "point"}], "curvature_extrema": [{"kind", "t",
/// "point", "curvature"}], "knots": [{"t", "multiplicity", "parametric", "geometric",
/// "tangent_angle"}]}, and the document's "revision". Every double reads back bit for bit.
/// @throws hula::Error as diffgeom::frenet, fins, inflections, curvature_extrema and knot_continuity
[[nodiscard]] std::string analysis_json(const curve::Curve& curve, const AnalysisRequest& request,
                                        std::uint64_t revision);

}  // namespace hula::server
