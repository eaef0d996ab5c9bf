// SPDX-License-Identifier: MIT
// JSON form of clothoid segments and splines; see the header.
#include "hula/io/clothoid_json.hpp"

namespace hula::io {

Json clothoid_segment_to_json(const intrinsic::ClothoidSegment& segment) {
  Json j = Json::object();
  j["start"] = point_to_json(segment.start, 2);
  j["theta0"] = segment.theta0;
  j["kappa0"] = segment.kappa0;
  j["dkappa"] = segment.dkappa;
  j["length"] = segment.length;
  j["end"] = point_to_json(segment.point(segment.length), 2);
  j["theta1"] = segment.angle(segment.length);
  j["kappa1"] = segment.curvature(segment.length);
  return j;
}

Json clothoid_spline_to_json(std::span<const intrinsic::ClothoidSegment> segments) {
  Json list = Json::array();
  double length = 0.0;
  for (const intrinsic::ClothoidSegment& s : segments) {
    list.push_back(clothoid_segment_to_json(s));
    length += s.length;
  }
  Json j = Json::object();
  j["segments"] = std::move(list);
  j["length"] = length;
  return j;
}

}  // namespace hula::io
