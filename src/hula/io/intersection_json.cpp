// SPDX-License-Identifier: MIT
// JSON of intersection and distance results (see the header).
#include "hula/io/intersection_json.hpp"

#include <algorithm>

namespace hula::io {

Json intersection_to_json(const nurbs::IntersectionResult& result, int dimension, double stand_in_deviation) {
  Json points = Json::array();
  for (const nurbs::CurveIntersection& p : result.points) {
    Json j = Json::object();
    j["s"] = p.s;
    j["t"] = p.t;
    j["point"] = point_to_json(p.point, dimension);
    j["distance"] = p.distance;
    j["angle"] = p.angle;
    j["kind"] = nurbs::intersection_kind_name(p.kind);
    points.push_back(std::move(j));
  }
  Json overlaps = Json::array();
  for (const nurbs::CurveOverlap& o : result.overlaps) {
    Json j = Json::object();
    j["s"] = Json::array({o.s0, o.s1});
    j["t"] = Json::array({o.t0, o.t1});
    j["start"] = point_to_json(o.start, dimension);
    j["end"] = point_to_json(o.end, dimension);
    overlaps.push_back(std::move(j));
  }
  Json out = Json::object();
  out["tolerance"] = result.tolerance;
  out["points"] = std::move(points);
  out["overlaps"] = std::move(overlaps);
  if (stand_in_deviation >= 0.0) out["stand_in_deviation"] = stand_in_deviation;
  return out;
}

Json curve_distance_to_json(const nurbs::CurveDistanceResult& result, int dimension, double stand_in_deviation) {
  Json out = Json::object();
  out["distance"] = result.distance;
  out["s"] = result.s;
  out["t"] = result.t;
  out["point_a"] = point_to_json(result.point_a, dimension);
  out["point_b"] = point_to_json(result.point_b, dimension);
  out["lower_bound"] = result.lower_bound;
  if (stand_in_deviation >= 0.0) out["stand_in_deviation"] = stand_in_deviation;
  return out;
}

namespace {

bool has_stand_in(const curve::Curve& c) { return c.kind() == curve::Kind::Law || c.kind() == curve::Kind::Natural; }

// The largest stand-in deviation of the curves that have one, else -1 (not written).
double stand_in(const curve::Curve& a, const curve::Curve* b) {
  double d = has_stand_in(a) ? a.approximation_deviation() : -1.0;
  if (b != nullptr && has_stand_in(*b)) d = std::max(d, b->approximation_deviation());
  return d;
}

}  // namespace

Json intersection_answer(const curve::Curve& a, const curve::Curve* b, const nurbs::IntersectOptions& options) {
  if (b == nullptr)
    return intersection_to_json(nurbs::self_intersect(a.nurbs(), options), a.nurbs().dimension(), stand_in(a, b));
  return intersection_to_json(nurbs::intersect(a.nurbs(), b->nurbs(), options),
                              std::max(a.nurbs().dimension(), b->nurbs().dimension()), stand_in(a, b));
}

Json distance_answer(const curve::Curve& a, const curve::Curve& b, const nurbs::IntersectOptions& options) {
  return curve_distance_to_json(nurbs::curve_distance(a.nurbs(), b.nurbs(), options),
                                std::max(a.nurbs().dimension(), b.nurbs().dimension()), stand_in(a, &b));
}

}  // namespace hula::io
