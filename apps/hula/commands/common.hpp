// SPDX-License-Identifier: MIT
// Shared pieces of the `hula` commands: the exit-code table, JSON output,
// parsing of command-line lists and end conditions (with hula::Error naming
// the option), and the small curve analyses that `info` and `demo` print
// (planarity, sampled maximum curvature, continuity at a knot).
//
// The analyses are local to the CLI until the diffgeom module provides them
// (DESIGN.md: continuity at knots and curvature extrema belong to diffgeom).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/law/expr.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::cli {

using Json = io::Json;

/// Exit codes of `hula` (documented in docs/cli.md and `hula --help`).
enum ExitCode : int {
  kExitOk = 0,            ///< success; the result JSON is on stdout
  kExitUsage = 2,         ///< bad command line (unknown option, missing argument); error JSON on stderr
  kExitInvalidInput = 3,  ///< hula::Error other than NumericalFailure: bad file, bad value, I/O failure
  kExitNumerical = 4,     ///< hula::Error(NumericalFailure): overflow or no convergence
  kExitInternal = 5,      ///< a bug in hula (InternalError or an unexpected exception)
};

/// Prints a JSON document on stdout (2-space indentation, final newline).
void print_json(const Json& document);

/// [x, y, z], or [x, y] when dimension is 2.
[[nodiscard]] Json vec_to_json(const Vec3& v, int dimension);

/// Parses a comma-separated list of numbers ("0,0.5,1").
/// @param text the option's value
/// @param field name used in messages and ErrorWhere.field (e.g. "t", "knots")
/// @throws hula::Error(Errc::ParseError) naming `field[i]` and the text of the bad entry
/// @throws hula::Error(Errc::NonFiniteInput) for nan/inf or a value outside the range of a double
[[nodiscard]] std::vector<double> parse_number_list(std::string_view text, std::string_view field);

/// Parses an END option: natural | bessel | not-a-knot | occt | clamped:x,y[,z].
/// @throws hula::Error(Errc::ParseError) naming `field` ("start" or "end") and the value
[[nodiscard]] nurbs::EndCondition parse_end_condition(std::string_view text, std::string_view field);

/// Result of the planarity test of a curve.
struct Planarity {
  bool planar = false;
  /// Unit normal of the plane (largest-magnitude component positive); absent
  /// when the control points are collinear or coincide (no unique plane).
  std::optional<Vec3> normal;
  /// Largest distance of a control point from the plane.
  double max_deviation = 0.0;
  /// The tolerance used: resolution_for_size(Tolerance{}, model size).
  double tolerance = 0.0;
};

/// Planarity of a curve, judged on its control points (a NURBS curve with
/// positive weights lies in a plane exactly when its control points do).
[[nodiscard]] Planarity planarity(const nurbs::NurbsCurve& curve);
/// JSON form: {"planar", "normal" ([x, y, z] or null), "max_deviation", "tolerance"}.
[[nodiscard]] Json planarity_to_json(const Planarity& p);

/// Largest curvature |C'×C''| / |C'|³ over `samples` + 1 uniformly spaced
/// parameters (both sides of every breakpoint are also sampled). An estimate:
/// a sharp peak between samples is missed.
/// @returns {"value", "t", "samples"}; value null if |C'| vanishes everywhere sampled
[[nodiscard]] Json max_curvature_estimate(const nurbs::NurbsCurve& curve, int samples = 1000);

/// The standard analysis of a curve printed by info and demo: degree, knots,
/// control points, weights, domain, rational, dimension, length (arc_length,
/// relative tolerance 1e-12), end derivatives C'(t0), C'(t1) and unit end
/// tangents (null where |C'| vanishes), planarity.
/// @throws hula::Error(Errc::NumericalFailure) if the arc length does not converge
[[nodiscard]] Json analyse(const nurbs::NurbsCurve& curve);

/// A registered subcommand and the function that runs it after parsing
/// (returns the exit code; hula::Error propagates to main).
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

/// `hula interpolate`: points file -> cubic spline curve file.
[[nodiscard]] Command add_interpolate(CLI::App& app);
/// `hula eval`: positions and derivatives at parameters.
[[nodiscard]] Command add_eval(CLI::App& app);
/// `hula analyse`: Frenet/Bishop frames, curvature, torsion and speed of a curve file.
[[nodiscard]] Command add_analyse(CLI::App& app);
/// `hula law`: evaluate, differentiate and analyse a law expression.
[[nodiscard]] Command add_law(CLI::App& app);
/// Values and derivatives 0..order of a law at parameters: result[i][k * dimension + c].
/// @throws hula::Error(Errc::OutOfDomain) naming `parameter[i]` where a value is undefined
[[nodiscard]] std::vector<std::vector<double>> law_derivatives(const law::Law& law, const std::string& parameter,
                                                               std::span<const double> ts, int order);
/// {"t", "derivatives": [[...], ...]} entries (the `hula eval` shape; scalars as one-element arrays).
[[nodiscard]] Json law_results_to_json(std::span<const double> ts, const std::vector<std::vector<double>>& values,
                                       int dimension, int order);
/// `hula reconstruct`: a curve from its curvature and torsion laws (natural equations).
[[nodiscard]] Command add_reconstruct(CLI::App& app);
/// `hula info`: the analysis of a curve file.
[[nodiscard]] Command add_info(CLI::App& app);
/// `hula demo`: the thesis's example curves (also the default command).
[[nodiscard]] Command add_demo(CLI::App& app);
/// `hula optimise`: a GA, NSGA-II or pagmo2 algorithm on a test problem or problem file.
[[nodiscard]] Command add_optimise(CLI::App& app);
/// `hula batch`: a campaign of study runs (commands/batch.cpp).
[[nodiscard]] Command add_batch(CLI::App& app);
/// `hula fair-knots`: knot-vector studies of thesis 7.2-7.4 from a "fair-knots" study file.
[[nodiscard]] Command add_fair_knots(CLI::App& app);
/// `hula fin-compound`: prescribed compound fins (projection technique, Combescure transform).
[[nodiscard]] Command add_fin_compound(CLI::App& app);
/// `hula edit-projection`: rebuild a 3-D curve from an edited projection.
[[nodiscard]] Command add_edit_projection(CLI::App& app);
/// `hula hermite`: Hermite editing of a spline's tangent and normal handles.
[[nodiscard]] Command add_hermite(CLI::App& app);
/// `hula match-curvature`: a prescribed curvature profile matched over data points (GA or hybrid).
[[nodiscard]] Command add_match_curvature(CLI::App& app);
/// `hula match-curvature-torsion`: curvature and torsion profiles as two objectives (NSGA-II).
[[nodiscard]] Command add_match_curvature_torsion(CLI::App& app);
/// Runs the demo and prints its JSON.
int run_demo();

}  // namespace hula::cli
