// SPDX-License-Identifier: MIT
// `hula intersect A B`, `hula intersect A --self` and `hula distance A B`:
// where two curves (or one curve with itself) meet and how far apart two
// curves are: io::intersection_answer / io::distance_answer, the answer every
// door gives (nurbs::intersect, self_intersect, curve_distance and their
// codec; law and natural-equation curves through their NURBS stand-in).
#include "hula/nurbs/intersect.hpp"

#include <memory>
#include <optional>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/intersection_json.hpp"

namespace hula::cli {

namespace {

struct IntersectArgs {
  std::string a;
  std::string b;
  bool self = false;
  std::optional<double> tolerance;
};

nurbs::IntersectOptions options_of(const IntersectArgs& args) {
  nurbs::IntersectOptions o;
  if (args.tolerance) o.tolerance.resabs = *args.tolerance;
  return o;
}

int run_intersect(const IntersectArgs& args) {
  if (args.self == !args.b.empty())
    throw Error(Errc::InvalidArgument,
                args.self ? "give either a second curve or --self, not both" : "give a second curve or --self",
                ErrorWhere{.field = "self"});
  const curve::Curve a = io::read_curve_file(args.a);
  std::optional<curve::Curve> b;
  if (!args.self) b = io::read_curve_file(args.b);
  Json doc = Json::object();
  doc["a"] = args.a;
  if (args.self)
    doc["self"] = true;
  else
    doc["b"] = args.b;
  Json answer = io::intersection_answer(a, b ? &*b : nullptr, options_of(args));
  for (auto& [key, value] : answer.items()) doc[key] = std::move(value);
  print_json(doc);
  return kExitOk;
}

int run_distance(const IntersectArgs& args) {
  const curve::Curve a = io::read_curve_file(args.a);
  const curve::Curve b = io::read_curve_file(args.b);
  Json doc = Json::object();
  doc["a"] = args.a;
  doc["b"] = args.b;
  Json answer = io::distance_answer(a, b, options_of(args));
  for (auto& [key, value] : answer.items()) doc[key] = std::move(value);
  print_json(doc);
  return kExitOk;
}

void add_tolerance(CLI::App* sub, IntersectArgs& args) {
  add_real_option(sub, "--tolerance", args.tolerance, 0.0, 1e300, true,
                  "Resolution: curves closer than this meet (model units; default 1e-6)");
}

}  // namespace

Command add_intersect(CLI::App& app) {
  auto a = std::make_shared<IntersectArgs>();
  CLI::App* sub = app.add_subcommand("intersect", "Where two curves meet, or where a curve meets itself (--self)");
  sub->add_option("a", a->a, "Curve file (JSON)")->required();
  sub->add_option("b", a->b, "Second curve file (JSON)");
  sub->add_flag("--self", a->self, "Self-intersections of the first curve");
  add_tolerance(sub, *a);
  return {sub, [a] { return run_intersect(*a); }};
}

Command add_distance(CLI::App& app) {
  auto a = std::make_shared<IntersectArgs>();
  CLI::App* sub = app.add_subcommand("distance", "The smallest distance between two curves and where it is reached");
  sub->add_option("a", a->a, "Curve file (JSON)")->required();
  sub->add_option("b", a->b, "Second curve file (JSON)")->required();
  add_tolerance(sub, *a);
  return {sub, [a] { return run_distance(*a); }};
}

}  // namespace hula::cli
