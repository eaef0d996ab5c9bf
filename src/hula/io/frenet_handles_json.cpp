// SPDX-License-Identifier: MIT
// Frenet handle files (see the header).
#include "hula/io/frenet_handles_json.hpp"

#include <string>

#include "hula/core/error.hpp"
#include "hula/io/json_read.hpp"

namespace hula::io {

FrenetHandles frenet_handles_from_json(const Json& document) {
  using namespace json;
  const JsonPath root = root_path("");
  if (!document.is_object())
    throw Error(Errc::ParseError, "a Frenet handle file is an object, got " + describe(document));
  reject_unknown_members(document, root, {"handles", "parameters"});
  const JsonPath hp = root.member("handles");
  const Json& list = get_array(require_member(document, root, "handles"), hp);
  FrenetHandles out;
  bool planar = true;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const JsonPath at = hp.element(i);
    const Json& h = list[i];
    if (!h.is_object()) throw Error(Errc::ParseError, at.text + ": a handle is an object", at.where);
    reject_unknown_members(h, at, {"point", "tangent", "normal", "curvature", "torsion"});
    nurbs::FrenetHandle f;
    const auto [p, pd] = get_point(require_member(h, at, "point"), at.member("point"));
    const auto [t, td] = get_point(require_member(h, at, "tangent"), at.member("tangent"));
    f.point = p;
    f.tangent = t;
    planar = planar && pd == 2 && td == 2;
    if (const Json* n = optional_member(h, "normal")) {
      const auto [nv, nd] = get_point(*n, at.member("normal"));
      f.normal = nv;
      planar = planar && nd == 2;
    }
    if (const Json* k = optional_member(h, "curvature")) f.curvature = get_number(*k, at.member("curvature"));
    if (const Json* tau = optional_member(h, "torsion")) f.torsion = get_number(*tau, at.member("torsion"));
    out.handles.push_back(f);
  }
  if (const Json* t = optional_member(document, "parameters"))
    out.parameters = get_number_array(*t, root.member("parameters"));
  out.dimension = planar ? 2 : 3;
  return out;
}

nurbs::NurbsCurve hermite_frenet_curve(const Json& document) {
  const FrenetHandles h = frenet_handles_from_json(document);
  return nurbs::hermite_frenet(h.handles, h.parameters, h.dimension);
}

}  // namespace hula::io
