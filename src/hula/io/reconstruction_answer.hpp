// SPDX-License-Identifier: MIT
// The one answer of a reconstruction from natural equations — the curve with
// curvature κ(s) and torsion τ(s) from a start frame (intrinsic::reconstruct,
// thesis 8.2.2), or, with an end point and/or end tangent held, the closest
// curve that meets them (studies::reconstruct_direct) — with its frames at
// arc lengths and its NURBS fit. `hula reconstruct` and POST
// /api/reconstruct both answer through it (they differ only in how they are
// asked and which members they print). The work is bounded
// (intrinsic::kFrontEndMaxSteps, kFrontEndMaxSegments) so a rough law is an
// error naming the limit, never minutes of work.
#pragma once

#include <optional>
#include <vector>

#include "hula/intrinsic/natural_equations.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/reconstruction_json.hpp"
#include "hula/law/expr.hpp"

namespace hula::io {

/// A reconstruction request in values.
struct ReconstructionQuery {
  law::Law kappa;  ///< κ(s), a law of "s" (signed when planar)
  law::Law tau;    ///< τ(s), a law of "s"
  double length = 0.0;
  intrinsic::StartFrame start{};
  double tolerance = 1e-10;  ///< position tolerance of the integration
  /// The NURBS fit: relative, at most intrinsic::kFrontEndMaxSegments segments (front_end_fit_options).
  intrinsic::NurbsFitOptions fit{};
  std::optional<std::vector<double>> at{};  ///< arc lengths of the frames (default 0, L/4, L/2, 3L/4, L)
  /// Held ends: with either, the boundary-value problem (studies::reconstruct_direct).
  std::optional<Vec3> end_point{}, end_tangent{};
  bool free_length = false;     ///< with a held end: the length may vary
  double end_tolerance = 1e-9;  ///< with a held end: relative to L
};

/// The fit options of a front end: `tolerance` relative to the curve's size, the front-end segment bound.
[[nodiscard]] intrinsic::NurbsFitOptions front_end_fit_options(double tolerance);

/// The reconstruction, its fit and their JSON members.
struct ReconstructionAnswer {
  std::optional<intrinsic::IntrinsicCurve> curve;  ///< always set
  std::optional<intrinsic::NurbsFitResult> fit;    ///< always set
  Json direct;       ///< with a held end: match_study_file's direct_reconstruction_summary; null otherwise
  Json points;       ///< frame_points_json at the query's arc lengths
  Json integration;  ///< integration_summary
  Json fit_summary;  ///< fit_summary
};

/// @throws hula::Error(Errc::InvalidArgument) naming "length" for a non-positive length with a held end;
///   as intrinsic::reconstruct, fit_nurbs_converged and studies::reconstruct_direct
[[nodiscard]] ReconstructionAnswer reconstruction_answer(const ReconstructionQuery& query);

/// Design by curvature on a curve value outside a document (`hula reconstruct --curve`;
/// oli::edit_curvature does the same on a document's entity): studies::edit_curvature with the request's
/// laws and options (curvature_edit_request_from_json reads the same request from JSON).
/// @throws as studies::edit_curvature
[[nodiscard]] studies::CurvatureEditResult curvature_edit_answer(const curve::Curve& curve,
                                                                 const CurvatureEditRequest& request);

}  // namespace hula::io
