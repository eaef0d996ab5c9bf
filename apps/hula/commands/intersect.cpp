// SPDX-License-Identifier: MIT
// `hula intersect A B`, `hula intersect A --self` and `hula distance A B`:
// where two curves (or one curve with itself) meet and how far apart two
// curves are (nurbs::intersect, nurbs::self_intersect, nurbs::curve_distance),
// printed with io::intersection_to_json / io::curve_distance_to_json. Law and
// natural-equation curves are answered through their NURBS stand-in, whose
// deviation is printed as "stand_in_deviation".
#include "hula/nurbs/intersect.hpp"

#include <algorithm>
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

bool has_stand_in(const curve::Curve& c) { return c.kind() == curve::Kind::Law || c.kind() == curve::Kind::Natural; }

// The largest stand-in deviation of the curves that have one, else -1 (not printed).
double stand_in(const curve::Curve& a, const curve::Curve* b) {
  double d = has_stand_in(a) ? a.approximation_deviation() : -1.0;
  if (b != nullptr && has_stand_in(*b)) d = std::max(d, b->approximation_deviation());
  return d;
}

int run_intersect(const IntersectArgs& args) {
  if (args.self == !args.b.empty())
    throw Error(Errc::InvalidArgument,
                args.self ? "give either a second curve or --self, not both" : "give a second curve or --self",
                ErrorWhere{.field = "self"});
  const curve::Curve a = io::read_curve_file(args.a);
  Json doc = Json::object();
  doc["a"] = args.a;
  Json result;
  if (args.self) {
    doc["self"] = true;
    result = io::intersection_to_json(nurbs::self_intersect(a.nurbs(), options_of(args)), a.nurbs().dimension(),
                                      stand_in(a, nullptr));
  } else {
    const curve::Curve b = io::read_curve_file(args.b);
    doc["b"] = args.b;
    result = io::intersection_to_json(nurbs::intersect(a.nurbs(), b.nurbs(), options_of(args)),
                                      std::max(a.nurbs().dimension(), b.nurbs().dimension()), stand_in(a, &b));
  }
  for (auto& [key, value] : result.items()) doc[key] = std::move(value);
  print_json(doc);
  return kExitOk;
}

int run_distance(const IntersectArgs& args) {
  const curve::Curve a = io::read_curve_file(args.a);
  const curve::Curve b = io::read_curve_file(args.b);
  Json doc = Json::object();
  doc["a"] = args.a;
  doc["b"] = args.b;
  Json result = io::curve_distance_to_json(nurbs::curve_distance(a.nurbs(), b.nurbs(), options_of(args)),
                                           std::max(a.nurbs().dimension(), b.nurbs().dimension()), stand_in(a, &b));
  for (auto& [key, value] : result.items()) doc[key] = std::move(value);
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
