// SPDX-License-Identifier: MIT
// Constraint checks and their JSON form (constraints.hpp). Curvature at an end
// is κ = |C' × C''| / |C'|³ (thesis eq. 11), from the curve's own derivatives
// (exact for law curves); the tangent residual is the angle between C' and
// the direction, by atan2(|a × b|, a · b), accurate at small angles.
#include "hula/oli/constraints.hpp"

#include <cmath>
#include <string>

#include "hula/core/error.hpp"
#include "hula/curve/curve.hpp"
#include "hula/nurbs/closest_point.hpp"

namespace hula::oli {

using Json = io::json::Json;

namespace {

void check_finite(double v, const char* member) {
  if (!std::isfinite(v))
    throw Error(Errc::NonFiniteInput, std::string(member) + " = " + format_number(v) + " is not finite",
                {.field = member});
}
void check_finite(const Vec3& v, const char* member) {
  for (std::size_t c = 0; c < 3; ++c)
    if (!std::isfinite(v[c]))
      throw Error(Errc::NonFiniteInput,
                  std::string(member) + "[" + std::to_string(c) + "] = " + format_number(v[c]) + " is not finite",
                  {.field = member, .component = c});
}

}  // namespace

std::string_view constraint_kind_name(ConstraintKind kind) noexcept {
  switch (kind) {
    case ConstraintKind::PassThrough:
      return "pass-through";
    case ConstraintKind::EndTangent:
      return "end-tangent";
    case ConstraintKind::EndCurvature:
      return "end-curvature";
    case ConstraintKind::FixedLength:
      return "fixed-length";
  }
  return "pass-through";
}

void Constraint::validate() const {
  check_finite(tolerance, "tolerance");
  if (tolerance <= 0.0)
    throw Error(Errc::InvalidArgument, "tolerance = " + format_number(tolerance) + " must be > 0",
                {.field = "tolerance"});
  switch (kind) {
    case ConstraintKind::PassThrough:
      check_finite(point, "point");
      break;
    case ConstraintKind::EndTangent:
      check_finite(direction, "direction");
      if (norm(direction) == 0.0)
        throw Error(Errc::InvalidArgument, "direction = [0, 0, 0] has no direction", {.field = "direction"});
      break;
    case ConstraintKind::EndCurvature:
      check_finite(value, "value");
      if (value < 0.0)
        throw Error(Errc::InvalidArgument, "curvature value = " + format_number(value) + " must be >= 0",
                    {.field = "value"});
      break;
    case ConstraintKind::FixedLength:
      check_finite(value, "value");
      if (value <= 0.0)
        throw Error(Errc::InvalidArgument, "length value = " + format_number(value) + " must be > 0",
                    {.field = "value"});
      break;
  }
}

std::vector<ConstraintResidual> check_constraints(const curve::Curve& curve, std::span<const Constraint> constraints) {
  std::vector<ConstraintResidual> out;
  out.reserve(constraints.size());
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    const Constraint& c = constraints[i];
    try {
      c.validate();
    } catch (const Error& e) {
      ErrorWhere where = e.where();
      where.index = i;
      throw Error(e.code(), "constraints[" + std::to_string(i) + "]: " + e.message(), where);
    }
    const double t_end = c.end == CurveEnd::Start ? curve.domain().start : curve.domain().end;
    double residual = 0.0;
    switch (c.kind) {
      case ConstraintKind::PassThrough:
        residual = nurbs::closest_point(curve.nurbs(), c.point).distance;
        break;
      case ConstraintKind::EndTangent: {
        const Vec3 d1 = curve.derivatives(t_end, 1)[1];
        residual = norm(d1) == 0.0 ? std::nan("") : std::atan2(norm(cross(d1, c.direction)), dot(d1, c.direction));
        break;
      }
      case ConstraintKind::EndCurvature: {
        const std::vector<Vec3> d = curve.derivatives(t_end, 2);
        const double speed = norm(d[1]);
        residual = speed == 0.0 ? std::nan("") : std::abs(norm(cross(d[1], d[2])) / (speed * speed * speed) - c.value);
        break;
      }
      case ConstraintKind::FixedLength:
        residual = std::abs(curve.length() - c.value);
        break;
    }
    out.push_back({i, c.kind, residual, residual <= c.tolerance});
  }
  return out;
}

io::json::Json constraints_to_json(std::span<const Constraint> constraints) {
  Json out = Json::array();
  for (const Constraint& c : constraints) {
    Json j = Json::object();
    j["kind"] = constraint_kind_name(c.kind);
    switch (c.kind) {
      case ConstraintKind::PassThrough:
        j["point"] = Json::array({c.point.x, c.point.y, c.point.z});
        break;
      case ConstraintKind::EndTangent:
        j["end"] = c.end == CurveEnd::Start ? "start" : "end";
        j["direction"] = Json::array({c.direction.x, c.direction.y, c.direction.z});
        break;
      case ConstraintKind::EndCurvature:
        j["end"] = c.end == CurveEnd::Start ? "start" : "end";
        j["value"] = c.value;
        break;
      case ConstraintKind::FixedLength:
        j["value"] = c.value;
        break;
    }
    j["tolerance"] = c.tolerance;
    out.push_back(std::move(j));
  }
  return out;
}

std::vector<Constraint> constraints_from_json(const io::json::Json& json) {
  namespace j = io::json;
  const j::JsonPath root = j::root_path("constraints");
  const auto& array = j::get_array(json, root);
  std::vector<Constraint> out;
  for (std::size_t i = 0; i < array.size(); ++i) {
    const j::JsonPath at = root.element(i);
    const auto& item = array[i];
    Constraint c;
    const std::string kind = j::get_string(j::require_member(item, at, "kind"), at.member("kind"));
    if (kind == "pass-through") {
      j::reject_unknown_members(item, at, {"kind", "point", "tolerance"});
      c.kind = ConstraintKind::PassThrough;
      c.point = j::get_point(j::require_member(item, at, "point"), at.member("point")).first;
    } else if (kind == "end-tangent" || kind == "end-curvature") {
      c.kind = kind == "end-tangent" ? ConstraintKind::EndTangent : ConstraintKind::EndCurvature;
      if (c.kind == ConstraintKind::EndTangent) {
        j::reject_unknown_members(item, at, {"kind", "end", "direction", "tolerance"});
        c.direction = j::get_point(j::require_member(item, at, "direction"), at.member("direction")).first;
      } else {
        j::reject_unknown_members(item, at, {"kind", "end", "value", "tolerance"});
        c.value = j::get_number(j::require_member(item, at, "value"), at.member("value"));
      }
      const std::string end = j::get_string(j::require_member(item, at, "end"), at.member("end"));
      if (end != "start" && end != "end") j::type_error(item.at("end"), at.member("end"), "\"start\" or \"end\"");
      c.end = end == "start" ? CurveEnd::Start : CurveEnd::End;
    } else if (kind == "fixed-length") {
      j::reject_unknown_members(item, at, {"kind", "value", "tolerance"});
      c.kind = ConstraintKind::FixedLength;
      c.value = j::get_number(j::require_member(item, at, "value"), at.member("value"));
    } else {
      j::type_error(item.at("kind"), at.member("kind"),
                    "one of \"pass-through\", \"end-tangent\", \"end-curvature\", \"fixed-length\"");
    }
    if (const auto* t = j::optional_member(item, "tolerance")) c.tolerance = j::get_number(*t, at.member("tolerance"));
    try {
      c.validate();
    } catch (const Error& e) {
      ErrorWhere where = e.where();
      where.index = i;
      throw Error(e.code(), "constraints[" + std::to_string(i) + "]: " + e.message(), where);
    }
    out.push_back(c);
  }
  return out;
}

}  // namespace hula::oli
