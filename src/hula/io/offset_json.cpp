// SPDX-License-Identifier: MIT
// JSON of offset curves (see the header).
#include "hula/io/offset_json.hpp"

#include <string>
#include <utility>

namespace hula::io {

Json planar_offset_to_json(const diffgeom::PlanarOffset& offset, double distance,
                           const diffgeom::OffsetOptions& options) {
  Json out = Json::object();
  out["distance"] = distance;
  out["tolerance"] = options.tolerance;
  out["exact"] = offset.exact;
  out["deviation"] = offset.deviation;
  out["raw"] = curve_to_json(offset.raw);
  out["cusps"] = offset.cusps;
  Json loops = Json::array();
  for (const nurbs::CurveIntersection& p : offset.loops) {
    Json j = Json::object();
    j["s"] = p.s;
    j["t"] = p.t;
    j["point"] = point_to_json(p.point, 2);
    j["angle"] = p.angle;
    loops.push_back(std::move(j));
  }
  out["loops"] = std::move(loops);
  Json trimmed = Json::array();
  for (const diffgeom::OffsetPiece& piece : offset.trimmed) {
    Json spans = Json::array();
    for (const Interval& s : piece.spans) spans.push_back(Json::array({s.start, s.end}));
    Json j = Json::object();
    j["spans"] = std::move(spans);
    j["closed"] = piece.closed;
    j["curve"] = curve_to_json(curve::Curve(piece.curve));
    trimmed.push_back(std::move(j));
  }
  out["trimmed"] = std::move(trimmed);
  return out;
}

Json offset_answer(const curve::Curve& curve, double distance, const diffgeom::OffsetOptions& options) {
  return planar_offset_to_json(diffgeom::planar_offset(curve, distance, options), distance, options);
}

Json helical_offset_to_json(const diffgeom::HelicalOffset& offset, std::string_view distance, std::string_view twist,
                            const diffgeom::HelicalOffsetOptions& options) {
  Json out = Json::object();
  out["frame"] = std::string(diffgeom::offset_frame_name(options.frame));
  out["distance"] = std::string(distance);
  out["twist"] = std::string(twist);
  out["tolerance"] = options.tolerance;
  out["exact"] = offset.exact;
  out["deviation"] = offset.deviation;
  if (offset.plane_normal) out["plane_normal"] = point_to_json(*offset.plane_normal, 3);
  out["curve"] = curve_to_json(offset.curve);
  return out;
}

Json helical_offset_answer(const curve::Curve& curve, std::string_view distance, std::string_view twist,
                           const diffgeom::HelicalOffsetOptions& options) {
  return helical_offset_to_json(diffgeom::helical_offset(curve, distance, twist, options), distance, twist, options);
}

Json mapped_curve_to_json(const diffgeom::MappedCurve& mapped, const Json& inputs,
                          const diffgeom::MappingOptions& options) {
  Json out = inputs;
  out["tolerance"] = options.tolerance;
  out["exact"] = mapped.exact;
  out["deviation"] = mapped.deviation;
  out["curve"] = curve_to_json(mapped.curve);
  return out;
}

Json orthotomic_answer(const curve::Curve& curve, const Vec3& pole, double k, const diffgeom::MappingOptions& options) {
  Json inputs = Json::object();
  inputs["mapping"] = "orthotomic";
  inputs["pole"] = point_to_json(pole, curve.dimension());
  inputs["k"] = k;
  return mapped_curve_to_json(diffgeom::orthotomic(curve, pole, k, options), inputs, options);
}

Json polar_answer(const curve::Curve& curve, const Vec3& centre, double radius,
                  const diffgeom::MappingOptions& options) {
  Json inputs = Json::object();
  inputs["mapping"] = "polar";
  inputs["centre"] = point_to_json(centre, 2);
  inputs["radius"] = radius;
  return mapped_curve_to_json(diffgeom::polar_map(curve, centre, radius, options), inputs, options);
}

}  // namespace hula::io
