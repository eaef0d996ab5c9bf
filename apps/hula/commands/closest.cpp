// SPDX-License-Identifier: MIT
// `hula closest CURVE --point x,y,z ...`: the point of the curve nearest to
// each given point (nurbs::closest_point: global search, Newton foot), as
// {"results": [{"point", "t", "closest", "distance"}]} (io::closest_answer).
#include <memory>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/curve_queries.hpp"

namespace hula::cli {

namespace {

struct ClosestArgs {
  std::string curve;
  std::vector<std::string> points;
  std::string format = "json";
};

int run_closest(const ClosestArgs& a) {
  const curve::Curve file = io::read_curve_file(a.curve);
  std::vector<Vec3> points;
  std::vector<int> dimensions;
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const std::vector<double> p = parse_number_list(a.points[i], "point");
    if (p.size() != 2 && p.size() != 3)
      throw Error(Errc::InvalidArgument, "--point " + a.points[i] + ": needs 2 or 3 numbers",
                  ErrorWhere{.field = "point", .index = i});
    points.push_back({p[0], p[1], p.size() == 3 ? p[2] : 0.0});
    dimensions.push_back(static_cast<int>(p.size()));
  }
  Json doc = Json::object();
  doc["curve"] = a.curve;
  doc.update(io::closest_answer(file, points, dimensions));
  print_formatted(doc, a.format, [](const Json& d) { return io::closest_table(d["results"]); });
  return kExitOk;
}

}  // namespace

Command add_closest(CLI::App& app) {
  auto a = std::make_shared<ClosestArgs>();
  CLI::App* sub = app.add_subcommand("closest", "The point of a curve nearest to given points");
  sub->add_option("curve", a->curve, "Curve file (JSON)")->required();
  sub->add_option("--point", a->points, "A point x,y[,z] (repeat the option for several)")->required();
  add_format_option(sub, a->format, "one result per line: point, t, closest, distance");
  return {sub, [a] { return run_closest(*a); }};
}

}  // namespace hula::cli
