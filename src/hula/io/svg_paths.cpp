// SPDX-License-Identifier: MIT
#include "hula/io/svg_paths.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

#include "hula/core/error.hpp"
#include "hula/io/svg.hpp"
#include "hula/nurbs/cubic_bezier.hpp"

namespace hula::io {
namespace {

// The shortest text that reads back to the same double.
std::string num(double value) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, ec == std::errc() ? end : buffer);
}

bool is_colour(const std::string& c) {
  return c.size() == 7 && c[0] == '#' &&
         std::all_of(c.begin() + 1, c.end(), [](char h) { return std::isxdigit(static_cast<unsigned char>(h)) != 0; });
}

}  // namespace

SvgPaths svg_paths(const std::vector<SvgPathCurve>& curves, const SvgPathOptions& options) {
  if (curves.empty()) throw Error(Errc::InvalidArgument, "no curves to write as SVG", {.field = "curves"});
  SvgPaths out;
  double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x, hi_x = -lo_x, hi_y = -lo_x;
  std::string paths;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const SvgPathCurve& c = curves[i];
    if (!is_colour(c.colour))
      throw Error(Errc::InvalidArgument,
                  "curves[" + std::to_string(i) + "].colour = \"" + c.colour + "\" is not \"#rrggbb\"",
                  {.field = "colour", .index = i});
    const nurbs::CubicPath path = nurbs::cubic_beziers(c.curve, options.tolerance);
    for (const Vec3& p : c.curve.control_points()) {
      lo_x = std::min(lo_x, p.x);
      hi_x = std::max(hi_x, p.x);
      lo_y = std::min(lo_y, p.y);
      hi_y = std::max(hi_y, p.y);
      if (p.z != 0.0) out.report.projected = true;
    }
    const double deviation = path.max_deviation + c.approximation_deviation;
    const bool exact = path.exact && c.approximation_deviation == 0.0;
    std::string d = "M " + num(path.pieces.front().points[0].x) + " " + num(path.pieces.front().points[0].y);
    for (const auto& piece : path.pieces) {
      d += " C";
      for (std::size_t k = 1; k < 4; ++k) d += " " + num(piece.points[k].x) + " " + num(piece.points[k].y);
    }
    paths += "    <path id=\"curve-" + std::to_string(i + 1) + "\" stroke=\"" + c.colour +
             "\" stroke-width=\"1\" vector-effect=\"non-scaling-stroke\" data-exact=\"" + (exact ? "true" : "false") +
             "\" data-max-deviation=\"" + num(deviation) + "\" d=\"" + d + "\">" +
             (c.name.empty() ? std::string() : "<title>" + xml_escape(c.name) + "</title>") + "</path>\n";
    ++out.report.curves;
    if (exact) ++out.report.exact;
    out.report.pieces += path.pieces.size();
    out.report.max_deviation = std::max(out.report.max_deviation, deviation);
  }
  // The viewBox of the flipped drawing: y runs from −hi_y down to −lo_y.
  const double size = std::max({hi_x - lo_x, hi_y - lo_y, 1e-9});
  const double margin = 0.02 * size;
  const double x0 = lo_x - margin, y0 = -hi_y - margin, w = hi_x - lo_x + 2 * margin, h = hi_y - lo_y + 2 * margin;
  out.text =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
      num(w) + "mm\" height=\"" + num(h) + "mm\" viewBox=\"" + num(x0) + " " + num(y0) + " " + num(w) + " " + num(h) +
      "\">\n"
      "  <desc>HulaHoops curves as cubic Bezier paths in model units (y up; z dropped). Exact for "
      "non-rational curves of degree 3 or less; otherwise within the data-max-deviation of each path "
      "(tolerance " +
      num(options.tolerance) +
      ").</desc>\n"
      "  <g transform=\"scale(1 -1)\" fill=\"none\">\n" +
      paths + "  </g>\n</svg>\n";
  return out;
}

}  // namespace hula::io
