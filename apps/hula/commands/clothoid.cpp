// SPDX-License-Identifier: MIT
// `hula clothoid`: Hermite interpolation by clothoids (intrinsic/clothoid.hpp). With end points and
// tangent angles only, the G1 clothoid (Bertolazzi–Frego 2015, one segment); with the end curvatures
// as well, the G2 spline of three clothoids (Bertolazzi–Frego 2018). JSON out:
// {"kind": "g1" | "g2", "segments": [...], "length", "iterations"} (io::clothoid_spline_to_json),
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

namespace hula::cli {

namespace {

struct ClothoidArgs {
  std::string start_point, end_point, at, output;
  std::optional<double> start_angle, end_angle, start_curvature, end_curvature, to_nurbs;
  double tolerance = curve::kNaturalTolerance;
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
  q.start_point = parse_xy(a.start_point, "start-point");
  q.end_point = parse_xy(a.end_point, "end-point");
  q.start_angle = *a.start_angle;
  q.end_angle = *a.end_angle;
  q.start_curvature = a.start_curvature;
  q.end_curvature = a.end_curvature;
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
      "clothoid", "Hermite interpolation by clothoids: G1 (one segment) or, with both curvatures, G2 (three)");
  constexpr double kMax = std::numeric_limits<double>::max();
  sub->add_option("--start-point", a->start_point, "Start point x,y")->required();
  add_real_option(sub, "--start-angle", a->start_angle, -kMax, kMax, false,
                  "Start tangent angle, radians from +x, counter-clockwise")
      ->required();
  sub->add_option("--end-point", a->end_point, "End point x,y")->required();
  add_real_option(sub, "--end-angle", a->end_angle, -kMax, kMax, false, "End tangent angle, radians")->required();
  CLI::Option* k0 = add_real_option(sub, "--start-curvature", a->start_curvature, -kMax, kMax, false,
                                    "Start curvature (> 0 turns left): asks for the G2 spline");
  CLI::Option* k1 = add_real_option(sub, "--end-curvature", a->end_curvature, -kMax, kMax, false,
                                    "End curvature: asks for the G2 spline");
  k0->needs(k1);
  k1->needs(k0);
  sub->add_option("--at", a->at, "Arc lengths s0,s1,... along the result at which to print point, angle, curvature");
  add_exact_output_options(sub, a->output, a->to_nurbs, a->tolerance);
  return {sub, [a] {
            if (!a->output.empty()) io::check_output_path(a->output, "--output");
            return run_clothoid(*a);
          }};
}

}  // namespace hula::cli
