// SPDX-License-Identifier: MIT
#include "commands/editing_common.hpp"

#include <algorithm>

#include "hula/io/atomic_file.hpp"
#include "hula/io/json_curve.hpp"

namespace hula::cli {

std::pair<double, double> in_plane(const Vec3& p, diffgeom::Plane plane) {
  switch (plane) {
    case diffgeom::Plane::XY:
      return {p.x, p.y};
    case diffgeom::Plane::YZ:
      return {p.y, p.z};
    case diffgeom::Plane::ZX:
      return {p.z, p.x};
  }
  return {p.x, p.y};
}

std::pair<std::string, std::string> plane_axes(diffgeom::Plane plane) {
  switch (plane) {
    case diffgeom::Plane::XY:
      return {"x", "y"};
    case diffgeom::Plane::YZ:
      return {"y", "z"};
    case diffgeom::Plane::ZX:
      return {"z", "x"};
  }
  return {"x", "y"};
}

io::SvgFigure plane_figure(const std::string& title, diffgeom::Plane plane) {
  io::SvgFigure f(640, 480);
  f.set_title(title);
  const auto [a, b] = plane_axes(plane);
  f.set_axes(a, b);
  f.set_equal_aspect(true);
  return f;
}

void draw_curve(io::SvgFigure& figure, const nurbs::NurbsCurve& curve, diffgeom::Plane plane, const io::SvgStyle& style,
                const std::string& legend, int samples) {
  std::vector<double> x, y;
  const nurbs::Interval d = curve.domain();
  for (int i = 0; i <= samples; ++i) {
    const double u = static_cast<double>(i) / samples;
    const auto [a, b] = in_plane(curve.evaluate(d.start * (1.0 - u) + d.end * u), plane);
    x.push_back(a);
    y.push_back(b);
  }
  figure.add_polyline(x, y, style, legend);
}

void draw_segments(io::SvgFigure& figure, std::span<const Vec3> base, std::span<const Vec3> tip, diffgeom::Plane plane,
                   const io::SvgStyle& style, const std::string& legend) {
  std::vector<double> x0, y0, x1, y1;
  for (std::size_t i = 0; i < base.size(); ++i) {
    const auto [a, b] = in_plane(base[i], plane);
    const auto [c, d] = in_plane(tip[i], plane);
    x0.push_back(a);
    y0.push_back(b);
    x1.push_back(c);
    y1.push_back(d);
  }
  figure.add_segments(x0, y0, x1, y1, style, legend);
}

void record_run(Json& output, const studies::StudyHeader& header, const StudyArgs& args) {
  output["seed"] = header.seed;
  output["threads"] = header.threads;
  output["log"] = args.log ? Json(*args.log) : Json(nullptr);
  if (args.log) io::write_file_atomically(*args.log, io::to_file_text(output));
}

}  // namespace hula::cli
