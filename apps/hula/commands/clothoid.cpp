// SPDX-License-Identifier: MIT
// `hula clothoid`: interpolation by clothoids (intrinsic/clothoid.hpp). With end points and
// tangent angles only, the G1 clothoid (Bertolazzi–Frego 2015, one segment); with the end curvatures
// as well, the G2 spline of three clothoids (Bertolazzi–Frego 2018); with --points FILE a G1 or G2
// clothoid spline through the points, open or --closed (an open one takes an angle or a curvature at
// each end); --biarc gives biarcs instead. JSON out:
// {"kind": "g1" | "g2" | "biarc", "segments": [...], "length", "iterations"} (io::clothoid_spline_to_json),
// and with --at the points, angles and curvatures at given arc lengths along the whole result.
// -o writes the result as a curve file by its curvature law (a natural curve, evaluated exactly:
// intrinsic::clothoid_natural_data), or with --to-nurbs TOL as its NURBS within TOL. The answer is
// io::clothoid_answer.
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/exact_curves.hpp"
#include "hula/io/points_file.hpp"

namespace hula::cli {

namespace {

struct ClothoidArgs {
  std::string start_point, end_point, at, output, points;
  std::optional<double> start_angle, end_angle, start_curvature, end_curvature, to_nurbs;
  double tolerance = curve::kNaturalTolerance;
  bool closed = false, g1 = false, g2 = false, biarc = false;
};

// A planar point x,y given as --<field>.
Vec3 parse_xy(const std::string& text, const char* field) {
  const std::vector<double> v = parse_number_list(text, field);
  if (v.size() != 2)
    throw Error(Errc::InvalidArgument,
                std::string("--") + field + " needs 2 numbers x,y (a planar point), got " + std::to_string(v.size()),
                ErrorWhere{.field = field});
  return {v[0], v[1], 0.0};
}

int run_clothoid(const ClothoidArgs& a) {
  io::ClothoidRequest q;
  if (!a.points.empty()) {
    // A spline through points: the end angles and curvatures are optional (open splines only).
    q.points = io::read_points_file(a.points).points;
    q.closed = a.closed;
    q.spline_start_angle = a.start_angle.has_value();
    q.spline_end_angle = a.end_angle.has_value();
  } else {
    for (const auto& [given, name] :
         {std::pair{!a.start_point.empty(), "--start-point"}, std::pair{a.start_angle.has_value(), "--start-angle"},
          std::pair{!a.end_point.empty(), "--end-point"}, std::pair{a.end_angle.has_value(), "--end-angle"}})
      if (!given) throw CLI::RequiredError(std::string(name) + " (or --points FILE)");
    if (a.closed) throw CLI::ValidationError("--closed", "needs --points (a Hermite problem is open)");
    q.start_point = parse_xy(a.start_point, "start-point");
    q.end_point = parse_xy(a.end_point, "end-point");
  }
  q.start_angle = a.start_angle.value_or(0.0);
  q.end_angle = a.end_angle.value_or(0.0);
  q.start_curvature = a.start_curvature;
  q.end_curvature = a.end_curvature;
  q.biarc = a.biarc;
  if (a.g1 || a.g2) q.continuity = a.g1 ? 1 : 2;
  if (!a.at.empty()) q.at = parse_number_list(a.at, "at");
  io::ClothoidAnswer answer = io::clothoid_answer(q);
  Json doc = std::move(answer.json);
  if (!a.output.empty())
    doc["output"] = io::write_exact_curve(a.output, io::clothoid_curve(answer.segments, a.tolerance), a.to_nurbs);
  print_result(doc, a.output);
  return kExitOk;
}

}  // namespace

Command add_clothoid(CLI::App& app) {
  auto a = std::make_shared<ClothoidArgs>();
  CLI::App* sub = app.add_subcommand(
      "clothoid",
      "Interpolation by clothoids or biarcs: Hermite G1 (one segment), G2 (three) or, with --points, a G1 / G2 "
      "spline through N points, open or closed");
  constexpr double kMax = std::numeric_limits<double>::max();
  CLI::Option* p0 = sub->add_option("--start-point", a->start_point, "Start point x,y (Hermite problem)");
  add_real_option(sub, "--start-angle", a->start_angle, -kMax, kMax, false,
                  "Start tangent angle, radians from +x, counter-clockwise (with --points: optional, open splines)");
  CLI::Option* p1 = sub->add_option("--end-point", a->end_point, "End point x,y (Hermite problem)");
  add_real_option(sub, "--end-angle", a->end_angle, -kMax, kMax, false, "End tangent angle, radians");
  CLI::Option* pts = sub->add_option(
      "--points", a->points,
      "Points file (JSON [[x,y],...] or lines x y): a spline through them instead of the Hermite problem");
  pts->excludes(p0);
  pts->excludes(p1);
  sub->add_flag("--closed", a->closed, "With --points: a closed spline (through the first point again)");
  CLI::Option* g1 = sub->add_flag("--g1", a->g1, "With --points: G1 (angles from three-point circles)");
  CLI::Option* g2 = sub->add_flag("--g2", a->g2, "With --points: G2, curvature continuous (the default)");
  CLI::Option* biarc =
      sub->add_flag("--biarc", a->biarc, "Biarcs (two circular arcs per interval, G1) instead of clothoids");
  g1->excludes(g2);
  biarc->excludes(g1);
  biarc->excludes(g2);
  CLI::Option* k0 = add_real_option(sub, "--start-curvature", a->start_curvature, -kMax, kMax, false,
                                    "Start curvature (> 0 turns left): with the end one, the G2 Hermite spline; "
                                    "with --points, the G2 spline's curvature at its first point");
  CLI::Option* k1 = add_real_option(sub, "--end-curvature", a->end_curvature, -kMax, kMax, false,
                                    "End curvature: with the start one, the G2 Hermite spline; with --points, the G2 "
                                    "spline's curvature at its last point");
  k0->excludes(biarc);
  k1->excludes(biarc);
  sub->add_option("--at", a->at, "Arc lengths s0,s1,... along the result at which to print point, angle, curvature");
  add_exact_output_options(sub, a->output, a->to_nurbs, a->tolerance);
  return {sub, [a] {
            if (!a->output.empty()) io::check_output_path(a->output, "--output");
            return run_clothoid(*a);
          }};
}

}  // namespace hula::cli
