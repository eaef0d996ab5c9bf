// SPDX-License-Identifier: MIT
// `hula reconstruct --kappa EXPR --tau EXPR --length L`: the curve with the
// given curvature and torsion laws of arc length `s` (thesis 8.2.2, eq. 34;
// hula::intrinsic::reconstruct), printed as position and Frenet frame at
// requested arc lengths plus a quintic NURBS fitted within the fit tolerance
// ({"points": [{"s", "position", "T", "N", "B"}], "integration": {"method",
// "steps", "rejected_steps", "breakpoints"}, "fit": {"control_points",
// "segments", "tolerance", "max_deviation"}}; control_points is the count).
// -o writes the fitted NURBS atomically, or with --exact the curve by its laws (a natural curve file,
// evaluated exactly wherever it is read: intrinsic::natural_curve). The work is bounded
// (intrinsic::kFrontEndMaxSteps, kFrontEndMaxSegments): a law too rough for
// them fails with an error naming kappa and the limit.
//
// With `--end-point x,y,z` and/or `--end-tangent x,y,z` (optionally `--free-length`) it solves the
// boundary-value problem of studies::reconstruct_direct instead (planar or space): the curve closest to
// the laws that meets the end, with the reconstruction's summary under "direct".
//
// With `--curve CURVE.json` it edits that curve instead (design by curvature, studies::edit_curvature):
// --kappa is the target κ(s) (or, with `--target change`, a change of |κ|) over the curve's own arc
// length, --tau (space curves, optional) its target torsion; `--hold free|tangent|curvature` says
// what the end keeps (default tangent: end point and end tangent; curvature: also both end
// curvatures), `--max-handles-factor` bounds the result's handles. Prints {"edit": the report} and
// writes the edited curve (same kind as the original where it can be) with -o.
//
// The answers are io::reconstruction_answer (shared with POST /api/reconstruct) and studies::edit_curvature
// through io (as the server's curvature-edit route).
#include <memory>
#include <optional>
#include <string>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/exact_curves.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/reconstruction_answer.hpp"
#include "hula/io/reconstruction_json.hpp"

namespace hula::cli {

namespace {

struct ReconstructArgs {
  std::string kappa;
  std::string tau;
  double length = 0.0;
  std::string start_point;
  std::string start_frame;
  double tolerance = 1e-10;
  double fit_tolerance = intrinsic::kFrontEndFitTolerance;
  std::string at;
  std::string output;
  std::string end_point;
  std::string end_tangent;
  bool free_length = false;
  double end_tolerance = 1e-9;
  std::string curve;
  std::string target = "curvature";
  std::string hold = "tangent";
  double max_handles_factor = 2.0;
  const CLI::Option* fit_tolerance_option = nullptr;
  const CLI::Option* length_option = nullptr;
  const CLI::Option* tau_option = nullptr;
  bool exact = false;
};

// A law of s given as --<field>, naming the option and the expression in errors.
law::Law parse_law(const std::string& text, law::Context& ctx, const char* field) {
  return io::natural_equation_law(text, ctx, field, std::string("--") + field);
}

Vec3 parse_vec(const std::string& text, const char* field) {
  const std::vector<double> v = parse_number_list(text, field);
  if (v.size() != 3)
    throw Error(Errc::InvalidArgument,
                std::string("--") + field + " needs 3 numbers x,y,z, got " + std::to_string(v.size()),
                ErrorWhere{.field = field});
  return {v[0], v[1], v[2]};
}

// --curve: design by curvature on the curve file (studies::edit_curvature, as the server's curvature-edit route).
int run_curvature_edit(const ReconstructArgs& a) {
  if (a.length_option->count() > 0)
    throw CLI::ValidationError("--length with --curve: the edited curve keeps its own length");
  if (a.exact) throw CLI::ValidationError("--exact with --curve: the edited curve is written as its own kind");
  if (a.fit_tolerance_option->count() > 0)
    throw CLI::ValidationError(
        "--fit-tolerance with --curve: the edited curve keeps the original's knots (at most "
        "--max-handles-factor times its handles), not a tolerance");
  law::Context ctx;
  io::CurvatureEditRequest request;
  request.edit.curvature = parse_law(a.kappa, ctx, "kappa");
  request.edit.target = studies::curvature_target_from_name(a.target, "target");
  if (a.tau_option->count() > 0) request.edit.torsion = parse_law(a.tau, ctx, "tau");
  request.options.hold = studies::end_hold_from_name(a.hold, "hold");
  request.options.max_handles_factor = a.max_handles_factor;
  request.options.reconstruction.max_steps = intrinsic::kFrontEndMaxSteps;
  request.options.validate();
  const curve::Curve original = io::read_curve_file(a.curve);
  const studies::CurvatureEditResult r = io::curvature_edit_answer(original, request);
  if (!a.output.empty()) io::write_curve_file(a.output, r.curve);
  Json doc = Json::object();
  doc["edit"] = io::curvature_edit_to_json(r);
  print_result(doc, a.output);
  return kExitOk;
}

int run_reconstruct(const ReconstructArgs& a) {
  if (!a.output.empty()) io::check_output_path(a.output, "--output");
  if (!a.curve.empty()) return run_curvature_edit(a);
  if (a.length_option->count() == 0) throw CLI::RequiredError("--length");
  if (a.tau_option->count() == 0) throw CLI::RequiredError("--tau");
  law::Context ctx;
  io::ReconstructionQuery q{.kappa = parse_law(a.kappa, ctx, "kappa"), .tau = parse_law(a.tau, ctx, "tau")};
  q.length = a.length;
  if (!a.start_point.empty()) q.start.point = parse_vec(a.start_point, "start-point");
  if (!a.start_frame.empty()) {
    const std::vector<double> v = parse_number_list(a.start_frame, "start-frame");
    if (v.size() != 6)
      throw Error(Errc::InvalidArgument,
                  "--start-frame needs 6 numbers Tx,Ty,Tz,Nx,Ny,Nz, got " + std::to_string(v.size()),
                  ErrorWhere{.field = "start-frame"});
    q.start.tangent = {v[0], v[1], v[2]};
    q.start.normal = {v[3], v[4], v[5]};
  }
  q.tolerance = a.tolerance;
  q.fit = io::front_end_fit_options(a.fit_tolerance);
  try {
    q.fit.validate();
  } catch (const Error& e) {
    throw Error(e.code(), "--fit-" + e.message(), ErrorWhere{.field = "fit-tolerance"});
  }
  const bool held = !a.end_point.empty() || !a.end_tangent.empty();
  if (a.exact && (held || a.output.empty()))
    throw Error(Errc::InvalidArgument,
                held ? "--exact writes the laws as given; with --end-point or --end-tangent the boundary-value problem "
                       "changes them: write its NURBS (without --exact)"
                     : "--exact needs -o FILE (it says what -o writes)",
                ErrorWhere{.field = "exact"});
  if (a.free_length && !held)
    throw Error(Errc::InvalidArgument, "--free-length needs --end-point or --end-tangent: a free end fixes no length",
                ErrorWhere{.field = "free-length"});
  if (!a.end_point.empty()) q.end_point = parse_vec(a.end_point, "end-point");
  if (!a.end_tangent.empty()) q.end_tangent = parse_vec(a.end_tangent, "end-tangent");
  q.free_length = a.free_length;
  q.end_tolerance = a.end_tolerance;
  if (!a.at.empty()) q.at = parse_number_list(a.at, "at");
  io::ReconstructionAnswer answer = io::reconstruction_answer(q);
  if (!a.output.empty() && a.exact) {
    const curve::NaturalData data{a.kappa,         a.tau,          "s",        a.length, q.start.point,
                                  q.start.tangent, q.start.normal, a.tolerance};
    io::write_curve_file(a.output, io::natural_equation_curve(data));
  } else if (!a.output.empty()) {
    io::write_curve_file(a.output, answer.fit->curve);
  }
  Json doc = Json::object();
  if (!answer.direct.is_null()) doc["direct"] = std::move(answer.direct);
  doc["points"] = std::move(answer.points);
  doc["integration"] = std::move(answer.integration);
  doc["fit"] = std::move(answer.fit_summary);
  print_result(doc, a.output);
  return kExitOk;
}

}  // namespace

Command add_reconstruct(CLI::App& app) {
  auto args = std::make_shared<ReconstructArgs>();
  CLI::App* sub = app.add_subcommand(
      "reconstruct", "Curve from its curvature and torsion laws of arc length s (natural equations, thesis 8.2.2)");
  sub->add_option("--kappa", args->kappa, "Curvature law of s, e.g. '1 + 0.5*sin(s)' (signed when planar)")->required();
  args->tau_option = sub->add_option("--tau", args->tau,
                                     "Torsion law of s, e.g. '0.3*cos(2*s)'; 0 gives a planar curve (required without "
                                     "--curve; with it, a space curve's target torsion)");
  args->length_option =
      sub->add_option("--length", args->length, "Arc length L > 0 of the curve (required without --curve)");
  sub->add_option("--start-point", args->start_point, "Start point x,y,z (default 0,0,0)");
  sub->add_option("--start-frame", args->start_frame,
                  "Start tangent and normal Tx,Ty,Tz,Nx,Ny,Nz (normalised, N made orthogonal to T; default "
                  "1,0,0,0,1,0)");
  sub->add_option("--tolerance", args->tolerance,
                  "Position tolerance of the integration (the printed points), in [1e-13, 1e-2] (default 1e-10)");
  args->fit_tolerance_option =
      sub->add_option("--fit-tolerance", args->fit_tolerance,
                      "Tolerance of the NURBS fit relative to the curve's size (bounding-box diagonal), in [1e-13, 1] "
                      "(default 1e-6; not with --curve)");
  sub->add_option("--at", args->at, "Arc lengths s0,s1,... in [0, L] to print (default 0, L/4, L/2, 3L/4, L)");
  sub->add_option("--end-point", args->end_point,
                  "Hold the end at x,y,z: the curve closest to the laws that reaches it (boundary-value problem)");
  sub->add_option("--end-tangent", args->end_tangent, "Hold the end tangent direction x,y,z (boundary-value problem)");
  sub->add_flag("--free-length", args->free_length,
                "Let the length vary from --length when an end is held (the laws then fix the shape, not the size)");
  sub->add_option("--end-tolerance", args->end_tolerance,
                  "End tolerance relative to L of the boundary-value problem, in [1e-13, 1e-2] (default 1e-9)");
  sub->add_option("--curve", args->curve,
                  "Edit this curve file's curvature instead (design by curvature): --kappa over its arc length s, its "
                  "ends kept per --hold");
  sub->add_option("--target", args->target,
                  "With --curve: --kappa is the target 'curvature' (signed when planar) or a 'change' of |κ|")
      ->check(CLI::IsMember({"curvature", "change"}));
  sub->add_option("--hold", args->hold,
                  "With --curve: what the end keeps: free, tangent (end point and tangent, default) or curvature "
                  "(also both end curvatures: G2)")
      ->check(CLI::IsMember({"free", "tangent", "curvature"}));
  sub->add_option("--max-handles-factor", args->max_handles_factor,
                  "With --curve: most handles of the result as a multiple of the original's, in [1, 10] (default 2)");
  sub->add_option("-o,--output", args->output,
                  "Write the fitted NURBS curve file (atomically); with --curve, the edited curve");
  sub->add_flag("--exact", args->exact,
                "With -o: write the exact curve by its laws (kind natural, integrated to --tolerance where it is read) "
                "instead of the fitted NURBS");
  return {sub, [args] { return run_reconstruct(*args); }};
}

}  // namespace hula::cli
