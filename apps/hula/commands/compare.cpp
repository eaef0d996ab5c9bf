// SPDX-License-Identifier: MIT
// Two-curve commands. `hula deviation A B`: the sampled distance between two
// curves (nurbs::deviation: thesis 10.2.2's position distance at equal
// normalised parameters, or the closest-point distance) with max, mean, RMS
// and per-axis figures. `hula continuity A B`: the continuity of the join of
// A's end with B's start (diffgeom::join_continuity: C0–C3, G0–G3, tangent
// angle, curvature on each side, the derivative table of thesis Table 3).
#include <cmath>
#include <memory>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/diffgeom/continuity.hpp"
#include "hula/nurbs/deviation.hpp"

namespace hula::cli {

namespace {

struct TwoCurves {
  std::string a;
  std::string b;
  std::size_t samples = 1001;
  std::string mode = "parameter";
};

Json axes(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }

int run_deviation(const TwoCurves& args) {
  const curve::Curve a = io::read_curve_file(args.a);
  const curve::Curve b = io::read_curve_file(args.b);
  nurbs::DeviationOptions o;
  o.samples = args.samples;
  if (args.mode == "parameter")
    o.mode = nurbs::DeviationMode::Parameter;
  else if (args.mode == "closest")
    o.mode = nurbs::DeviationMode::Closest;
  else
    throw Error(Errc::InvalidArgument, "--mode " + args.mode + ": expected parameter or closest",
                ErrorWhere{.field = "mode"});
  const nurbs::DeviationResult r = nurbs::deviation(a.nurbs(), b.nurbs(), o);
  Json doc = Json::object();
  doc["a"] = args.a;
  doc["b"] = args.b;
  doc["mode"] = args.mode;
  doc["samples"] = r.samples;
  doc["max"] = r.max;
  doc["max_at"] = r.at;
  doc["mean"] = r.mean;
  doc["rms"] = r.rms;
  doc["mean_axis"] = axes(r.mean_axis);
  doc["max_axis"] = axes(r.max_axis);
  print_json(doc);
  return kExitOk;
}

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json order_name(char prefix, int k) { return k < 0 ? Json(nullptr) : Json(std::string(1, prefix) + std::to_string(k)); }

int run_continuity(const TwoCurves& args) {
  const curve::Curve a = io::read_curve_file(args.a);
  const curve::Curve b = io::read_curve_file(args.b);
  const diffgeom::Continuity c = diffgeom::join_continuity(a.nurbs(), b.nurbs());
  const int dim = std::max(a.nurbs().dimension(), b.nurbs().dimension());
  Json left = Json::array(), right = Json::array();
  for (std::size_t k = 0; k < 4; ++k) {
    left.push_back(vec_to_json(c.left[k], dim));
    right.push_back(vec_to_json(c.right[k], dim));
  }
  Json doc = Json::object();
  doc["a"] = args.a;
  doc["b"] = args.b;
  doc["parametric"] = order_name('C', c.parametric);
  doc["geometric"] = order_name('G', c.geometric);
  doc["tangent_angle"] = number_or_null(c.tangent_angle);
  doc["curvature_left"] = number_or_null(c.curvature_left);
  doc["curvature_right"] = number_or_null(c.curvature_right);
  doc["left"] = std::move(left);
  doc["right"] = std::move(right);
  print_json(doc);
  return kExitOk;
}

}  // namespace

Command add_deviation(CLI::App& app) {
  auto a = std::make_shared<TwoCurves>();
  CLI::App* sub = app.add_subcommand("deviation", "Distance between two curves: max, mean, RMS, per axis");
  sub->add_option("a", a->a, "Reference curve file (JSON)")->required();
  sub->add_option("b", a->b, "Compared curve file (JSON)")->required();
  sub->add_option("--samples", a->samples, "Samples, ends included, >= 2 (default 1001)")
      ->check(CLI::Range(std::size_t{2}, std::size_t{10'000'000}));
  sub->add_option("--mode", a->mode,
                  "parameter: A(s) vs B(s) at equal normalised parameters (thesis 10.2.2, default); "
                  "closest: A(s) vs the nearest point of B");
  return {sub, [a] { return run_deviation(*a); }};
}

Command add_continuity(CLI::App& app) {
  auto a = std::make_shared<TwoCurves>();
  CLI::App* sub = app.add_subcommand("continuity", "Continuity (C0-C3, G0-G3) of the join of A's end with B's start");
  sub->add_option("a", a->a, "First curve file (its end)")->required();
  sub->add_option("b", a->b, "Second curve file (its start)")->required();
  return {sub, [a] { return run_continuity(*a); }};
}

}  // namespace hula::cli
