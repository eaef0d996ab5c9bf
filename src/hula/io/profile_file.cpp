// SPDX-License-Identifier: MIT
// The codec of target profiles (profile_file.hpp).
#include "hula/io/profile_file.hpp"

#include <filesystem>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/io/points_file.hpp"
#include "hula/law/parser.hpp"

namespace hula::io {

studies::Profile profile_from_json(const Json& value, const json::JsonPath& path, const PathResolver& resolver,
                                   const law::Context& context) {
  using studies::Profile;
  if (!value.is_object()) json::type_error(value, path, "an object with one of law, samples, csv, bspline");
  if (const Json* text = json::optional_member(value, "law")) {
    json::reject_unknown_members(value, path, {"law", "variable"});
    std::string variable = "u";
    if (const Json* v = json::optional_member(value, "variable"))
      variable = json::get_string(*v, path.member("variable"));
    const std::string expr = json::get_string(*text, path.member("law"));
    try {
      law::ParseOptions options;
      options.parameters = {variable};
      return Profile::from_law(law::parse(expr, context, options), variable);
    } catch (const Error& e) {
      throw Error(e.code(), path.member("law").text + ": " + e.message(), path.member("law").where);
    }
  }
  if (const Json* samples = json::optional_member(value, "samples")) {
    json::reject_unknown_members(value, path, {"samples"});
    const json::PointArray pts = json::get_points(*samples, path.member("samples"));
    std::vector<double> u(pts.points.size()), v(pts.points.size());
    for (std::size_t i = 0; i < u.size(); ++i) {
      if (pts.dimension != 2) json::type_error(*samples, path.member("samples"), "an array of [u, value] pairs");
      u[i] = pts.points[i].x;
      v[i] = pts.points[i].y;
    }
    return Profile::from_samples(u, v, context);
  }
  if (const Json* csv = json::optional_member(value, "csv")) {
    json::reject_unknown_members(value, path, {"csv"});
    const std::string name = json::get_string(*csv, path.member("csv"));
    const std::filesystem::path file = resolver(name, path.member("csv").text);
    const PointSet pts = read_points_file(file);
    if (pts.dimension != 2)
      throw Error(Errc::ParseError, path.member("csv").text + ": '" + name + "' must have two columns (u, value)",
                  path.member("csv").where);
    std::vector<double> u(pts.points.size()), v(pts.points.size());
    for (std::size_t i = 0; i < u.size(); ++i) {
      u[i] = pts.points[i].x;
      v[i] = pts.points[i].y;
    }
    return Profile::from_samples(u, v, context);
  }
  if (const Json* b = json::optional_member(value, "bspline")) {
    json::reject_unknown_members(value, path, {"bspline"});
    const json::JsonPath bp = path.member("bspline");
    json::reject_unknown_members(*b, bp, {"degree", "knots", "coefficients"});
    const int degree =
        static_cast<int>(json::get_integer(json::require_member(*b, bp, "degree"), bp.member("degree"), 1, 64));
    const auto knots = json::get_number_array(json::require_member(*b, bp, "knots"), bp.member("knots"));
    const auto coefficients =
        json::get_number_array(json::require_member(*b, bp, "coefficients"), bp.member("coefficients"));
    return Profile::from_bspline(degree, knots, coefficients, context);
  }
  throw Error(Errc::ParseError, path.text + ": a profile needs one of \"law\", \"samples\", \"csv\", \"bspline\"",
              path.where);
}

}  // namespace hula::io
