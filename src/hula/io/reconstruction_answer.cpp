// SPDX-License-Identifier: MIT
// The answer of a reconstruction from natural equations (reconstruction_answer.hpp).
#include "hula/io/reconstruction_answer.hpp"

#include <cmath>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/io/match_study_file.hpp"
#include "hula/io/reconstruction_json.hpp"
#include "hula/law/derive.hpp"
#include "hula/studies/direct_reconstruction.hpp"

namespace hula::io {

intrinsic::NurbsFitOptions front_end_fit_options(double tolerance) {
  intrinsic::NurbsFitOptions o;
  o.tolerance = tolerance;
  o.relative = true;
  o.max_segments = intrinsic::kFrontEndMaxSegments;
  return o;
}

ReconstructionAnswer reconstruction_answer(const ReconstructionQuery& q) {
  ReconstructionAnswer out;
  if (q.end_point || q.end_tangent) {
    // The laws of s as profiles of u = s / L (reconstruct_direct's abscissa), for the boundary-value problem.
    if (!std::isfinite(q.length) || !(q.length > 0.0))
      throw Error(Errc::InvalidArgument, "--length = " + format_number(q.length) + " must be positive and finite",
                  ErrorWhere{.field = "length"});
    law::Context ctx = q.kappa.context();  // the laws' own context: u joins them there
    const law::Law s_of_u = q.length * ctx.parameter("u");
    studies::DirectReconstructionProblem p{.curvature =
                                               studies::Profile::from_law(law::substitute(q.kappa, "s", s_of_u))};
    if (!(q.tau.is_constant() && q.tau.node().value == 0.0))
      p.torsion = studies::Profile::from_law(law::substitute(q.tau, "s", s_of_u));
    p.length = q.length;
    p.start = q.start;
    p.end_point = q.end_point;
    p.end_tangent = q.end_tangent;
    studies::DirectReconstructionOptions o;
    o.vary_length = q.free_length;
    o.end_tolerance = q.end_tolerance;
    o.fit_options = q.fit;
    studies::DirectReconstructionResult r = studies::reconstruct_direct(p, o);
    out.direct = direct_reconstruction_summary(r);
    out.curve = std::move(r.curve);
    out.fit = std::move(r.nurbs);
  } else {
    intrinsic::ReconstructionOptions options;
    options.tolerance = q.tolerance;
    options.max_steps = intrinsic::kFrontEndMaxSteps;
    out.curve = intrinsic::reconstruct(q.kappa, q.tau, "s", q.length, q.start, options);
    out.fit = intrinsic::fit_nurbs_converged(*out.curve, q.fit);
  }
  const double length = out.curve->length();
  std::vector<double> ss;
  if (q.at)
    ss = *q.at;
  else
    for (int i = 0; i <= 4; ++i) ss.push_back(i == 4 ? length : length * i / 4.0);
  out.points = frame_points_json(out.curve->evaluate(ss));
  out.integration = integration_summary(*out.curve);
  out.fit_summary = fit_summary(*out.fit);
  return out;
}

studies::CurvatureEditResult curvature_edit_answer(const curve::Curve& curve, const CurvatureEditRequest& request) {
  return studies::edit_curvature(curve, request.edit, request.options);
}

}  // namespace hula::io
