// SPDX-License-Identifier: MIT
// The study files of the editing studies (docs/formats.md, study kinds
// "fin-compound", "edit-projection" and "hermite"): readers that check every
// member before any work (unknown members, wrong plane, non-planar edits,
// mismatched counts are errors naming the member), and the resolved setup as
// JSON so that a run can be repeated exactly.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "hula/io/json_curve.hpp"
#include "hula/io/study_file.hpp"
#include "hula/studies/fin_compound.hpp"
#include "hula/studies/hermite_edit.hpp"
#include "hula/studies/projection_edit.hpp"

namespace hula::io {

/// Reads member `name` of a study body as an inline curve document (docs/formats.md curve files:
/// "nurbs", "bezier", "interpolated" or "law").
/// @throws hula::Error(Errc::ParseError) if it is missing; errors of io::curve_from_json with the
///   member name prefixed to the message and the field ("curve.control_points")
[[nodiscard]] curve::Curve read_curve_member(const Json& body, std::string_view name);

/// Which technique a "fin-compound" study runs.
enum class FinCompoundMethod {
  Projection,  ///< the projection technique (normal fin compound of a projection)
  Combescure,  ///< the Combescure transform and its inverse
};

/// A "fin-compound" study.
struct FinCompoundStudy {
  studies::StudyHeader header{};
  FinCompoundMethod method = FinCompoundMethod::Projection;
  /// "curve": the original curve (projection: required; combescure: the parent, forward transform).
  std::optional<curve::Curve> curve{};
  /// "compound": the edited / prescribed compound (projection: optional, without it only the compound
  /// is computed; combescure: the prescribed compound, inverse transform). One of curve/compound for
  /// combescure.
  std::optional<curve::Curve> compound{};
  /// "plane", "scale", "samples", "min_stretch", "tolerance" (projection).
  studies::NormalCompoundOptions projection{};
  /// "c", "samples", "tolerance" (combescure).
  studies::CombescureOptions combescure{};
};

/// Reads a "fin-compound" study body.
/// @throws hula::Error(Errc::ParseError) naming an unknown or missing member or a bad value;
///   hula::Error(Errc::InvalidArgument) naming "plane" or "compound" (not planar in the plane);
///   hula::Error(Errc::InvalidOption) naming the option out of range
[[nodiscard]] FinCompoundStudy read_fin_compound_study(const StudyDocument& doc);

/// What a "fin-compound" run computed (run_fin_compound_study).
struct FinCompoundRun {
  /// projection: "curve" projected on the plane.
  std::optional<nurbs::NurbsCurve> projection{};
  /// projection: the normal fin compound of the projection; combescure with "curve": its compound.
  std::optional<studies::LawCurveFit> compound{};
  /// projection with "compound": the new projection and the rebuilt 3-D curve.
  std::optional<studies::CompoundEditResult> edit{};
  /// combescure with "compound": the parent whose compound it is.
  std::optional<studies::LawCurveFit> parent{};
  /// combescure: max |transform back (with −c, resp. +c) − input| at 1001 parameters of the input's domain.
  double round_trip_deviation = 0.0;
  /// The run's result curve (`hula fin-compound -o`): the rebuilt 3-D curve, else the compound, else the parent.
  [[nodiscard]] const nurbs::NurbsCurve& result_curve() const;
};

/// Runs a "fin-compound" study (thesis 8.3): projection — the projection's normal fin compound and, given
/// "compound", the edit; combescure — the compound of "curve" or the parent of "compound" (law curves
/// transformed exactly, NURBS as laws of "t") with the round-trip check.
/// @throws the errors of the studies' functions; hula::Error(Errc::NumericalFailure) when the transform
///   back is undefined at a checked parameter
[[nodiscard]] FinCompoundRun run_fin_compound_study(const FinCompoundStudy& study);

/// The result of a fin-compound run, as `hula fin-compound` prints it (without the CLI's seed, threads and
/// log): {"study": "fin-compound", "method", then projection: "plane", "scale", "projection" (curve file),
/// "compound": {"curve", "fit_deviation"}, "edit": {"planar", "curve", "min_stretch", "min_stretch_at",
/// "forward_deviation", "assembly_deviation", "max_change": [x, y, z]}; combescure: "c", "compound" or
/// "parent": {"curve", "fit_deviation", "round_trip_deviation"}} (docs/formats.md).
[[nodiscard]] Json fin_compound_result_to_json(const FinCompoundStudy& study, const FinCompoundRun& run);

/// An "edit-projection" study.
struct EditProjectionStudy {
  studies::StudyHeader header{};
  curve::Curve curve;                           ///< "curve": the original 3-D curve
  curve::Curve edited;                          ///< "edited": the edited projection, planar in `plane`
  diffgeom::Plane plane = diffgeom::Plane::XY;  ///< "plane"
};

/// Reads an "edit-projection" study body.
/// @throws as read_fin_compound_study; InvalidArgument naming "edited" if it is not planar in the plane
[[nodiscard]] EditProjectionStudy read_edit_projection_study(const StudyDocument& doc);

/// The result of an edit-projection run, as `hula edit-projection` prints it (without the CLI's seed,
/// threads and log): {"study": "edit-projection", "plane", "parameter_match": "normalised", "curve": the
/// rebuilt curve file, "max_deviation", "max_change": [x, y, z] the largest change of each coordinate from
/// the original at 1001 points of equal normalised parameter}.
[[nodiscard]] Json edit_projection_result_to_json(const EditProjectionStudy& study,
                                                  const studies::ProjectionEditResult& result);

/// A "hermite" study.
struct HermiteStudy {
  studies::StudyHeader header{};
  /// "spline": an "interpolated" curve document (points, parameterisation or parameters, ends).
  curve::InterpolatedData spline{};
  /// The spline's interpolation options and "rebuild".
  studies::HermiteEditOptions options{};
  /// "edits" (angles in the file in degrees, here in radians).
  std::vector<studies::HandleEdit> edits;
};

/// Reads a "hermite" study body.
/// @throws hula::Error(Errc::ParseError) naming the member ("spline" not of kind "interpolated", an
///   unknown edit member); the errors of the interpolated curve reader (e.g. "spline.parameters" whose
///   count differs from the points'); hula::Error(Errc::InvalidArgument) naming "edits[i].<field>"
///   for a bad edit (hermite_edit's checks, run here before any work)
[[nodiscard]] HermiteStudy read_hermite_study(const StudyDocument& doc);

/// The result of a hermite run, as `hula hermite` prints it (without the CLI's seed, threads and log):
/// {"study": "hermite", "rebuild", "spline" and "curve" (curve files), "before" and "after" (per knot:
/// "t", "point", "first", "second", "tangent_handle", "normal_handle"), "max_distance_from_spline" (at
/// 1001 points of equal normalised parameter)}.
[[nodiscard]] Json hermite_result_to_json(const HermiteStudy& study, const studies::HermiteEditResult& result);

}  // namespace hula::io
