// SPDX-License-Identifier: MIT
// The curve analysis codec (curve_analysis_json.hpp).
#include "hula/io/curve_analysis_json.hpp"

#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/io/intersection_json.hpp"

namespace hula::io {

namespace {

using json::Json;

bool read_bool(const Json& v, std::string_view name) {
  if (!v.is_boolean()) json::type_error(v, json::root_path(name), "true or false");
  return v.get<bool>();
}

void write_features(JsonText& w, const diffgeom::CurveFeatures& f) {
  w.begin_object();
  w.member("inflections").containers(f.inflections.size(), [&](std::size_t i) {
    w.begin_object().member("t").number(f.inflections[i].t).member("point").vec(f.inflections[i].position);
    w.end_object();
  });
  const auto extrema = [&w](const std::vector<diffgeom::Feature>& list, bool curvature) {
    w.containers(list.size(), [&](std::size_t i) {
      const diffgeom::Feature& e = list[i];
      w.begin_object().member("kind").string(extremum_kind_name(e.kind)).member("t").number(e.t);
      w.member("point").vec(e.position);
      w.member(curvature ? "curvature" : "torsion").number(curvature ? e.curvature : e.torsion);
      w.end_object();
    });
  };
  w.member("curvature_extrema");
  extrema(f.curvature_extrema, true);
  w.member("torsion_extrema");
  extrema(f.torsion_extrema, false);
  w.member("knots").containers(f.knots.size(), [&](std::size_t i) { w.value(continuity_to_json(f.knots[i])); });
  const diffgeom::CurvatureMonotonicity& m = f.monotonicity;
  w.member("curvature_monotonicity").begin_object().member("monotone").boolean(m.monotone());
  w.member("pieces").containers(m.pieces.size(), [&](std::size_t i) {
    const diffgeom::MonotonePiece& p = m.pieces[i];
    w.begin_object().member("t0").number(p.t0).member("t1").number(p.t1);
    w.member("curvature0").number(p.kappa0).member("curvature1").number(p.kappa1);
    w.member("trend").string(diffgeom::curvature_trend_name(p.trend)).end_object();
  });
  w.member("violations").containers(m.violations.size(), [&](std::size_t i) {
    const diffgeom::Feature& v = m.violations[i];
    w.begin_object().member("kind").string(extremum_kind_name(v.kind)).member("t").number(v.t);
    w.member("curvature").number(v.curvature).end_object();
  });
  w.end_object();
  w.member("maximum_curvature").value(maximum_curvature_to_json(f.maximum_curvature));
  w.member("self_intersections").value(intersection_to_json(f.self_intersections, 3));
  w.end_object();
}

}  // namespace

json::Json continuity_to_json(const diffgeom::Continuity& k) {
  const auto number = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  const auto vectors = [](const std::array<Vec3, 4>& d) {
    Json a = Json::array();
    for (const Vec3& v : d) a.push_back(is_finite(v) ? Json::array({v.x, v.y, v.z}) : Json(nullptr));
    return a;
  };
  // Ck and Gk as k; null where not even C0 (G0).
  return Json{{"t", k.t},
              {"multiplicity", k.multiplicity},
              {"parametric", k.parametric >= 0 ? Json(k.parametric) : Json(nullptr)},
              {"geometric", k.geometric >= 0 ? Json(k.geometric) : Json(nullptr)},
              {"tangent_angle", number(k.tangent_angle)},
              {"curvature_left", number(k.curvature_left)},
              {"curvature_right", number(k.curvature_right)},
              {"left", vectors(k.left)},
              {"right", vectors(k.right)}};
}

json::Json planarity_to_json(const diffgeom::Planarity& p) {
  Json o = Json::object();
  o["planar"] = p.planar;
  o["normal"] = p.normal ? Json::array({p.normal->x, p.normal->y, p.normal->z}) : Json(nullptr);
  o["max_deviation"] = p.max_deviation;
  o["tolerance"] = p.tolerance;
  return o;
}

json::Json maximum_curvature_to_json(const diffgeom::MaximumCurvature& m) {
  const bool defined = std::isfinite(m.value);
  return Json{{"value", defined ? Json(m.value) : Json(nullptr)}, {"t", defined ? Json(m.t) : Json(nullptr)}};
}

std::string_view extremum_kind_name(diffgeom::FeatureKind kind) noexcept {
  return kind == diffgeom::FeatureKind::CurvatureMaximum || kind == diffgeom::FeatureKind::TorsionMaximum ? "maximum"
                                                                                                          : "minimum";
}

diffgeom::AnalysisOptions analysis_options_from_json(const Json& body, const diffgeom::AnalysisOptions& defaults) {
  const json::JsonPath root;
  if (!body.is_object()) json::type_error(body, root, "an object");
  json::reject_unknown_members(
      body, root, {"samples", "at", "by", "arc_lengths", "bishop", "fins", "scale", "fin_density", "features"});
  diffgeom::AnalysisOptions o = defaults;
  if (const Json* n = json::optional_member(body, "samples"))
    o.samples = static_cast<int>(json::get_integer(*n, json::root_path("samples"), 1, diffgeom::kMaxAnalysisSamples));
  if (const Json* at = json::optional_member(body, "at")) o.at = json::get_number_array(*at, json::root_path("at"));
  if (const Json* by = json::optional_member(body, "by")) {
    const std::string b = json::get_string(*by, json::root_path("by"));
    const std::optional<diffgeom::SampleBy> s = diffgeom::sample_by_from_name(b);
    if (!s)
      throw Error(Errc::InvalidOption, "by = \"" + b + "\" is not \"parameter\" or \"arclength\"",
                  ErrorWhere{.field = "by"});
    o.by = *s;
  }
  if (const Json* a = json::optional_member(body, "arc_lengths")) o.arc_lengths = read_bool(*a, "arc_lengths");
  if (const Json* b = json::optional_member(body, "bishop")) o.bishop = read_bool(*b, "bishop");
  if (const Json* fins = json::optional_member(body, "fins")) {
    const Json& list = json::get_array(*fins, json::root_path("fins"));
    o.fins.clear();
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string name = json::get_string(list[i], json::root_path("fins").element(i));
      const std::optional<diffgeom::FinKind> k = diffgeom::fin_kind_from_name(name);
      if (!k)
        throw Error(Errc::InvalidOption,
                    "fins[" + std::to_string(i) + "] = \"" + name +
                        "\" is not a fin (curvature, torsion, normal, binormal, bishop-u, bishop-v, combescure)",
                    ErrorWhere{.field = "fins", .index = i});
      o.fins.push_back(*k);
    }
  }
  if (const Json* s = json::optional_member(body, "scale")) {
    const double scale = json::get_number(*s, json::root_path("scale"));
    if (!(scale != 0.0)) throw Error(Errc::InvalidOption, "scale = 0 must be non-zero", ErrorWhere{.field = "scale"});
    o.fin_scale = scale;
  }
  if (const Json* d = json::optional_member(body, "fin_density"))
    o.fin_density =
        static_cast<int>(json::get_integer(*d, json::root_path("fin_density"), 0, diffgeom::kMaxAnalysisSamples));
  if (const Json* f = json::optional_member(body, "features")) o.features = read_bool(*f, "features");
  o.validate();
  return o;
}

void write_curve_analysis_members(JsonText& w, const diffgeom::CurveAnalysis& a) {
  const std::span<const diffgeom::FrenetPoint> f = a.samples;
  const std::size_t n = f.size();
  w.member("t").scalars(n, [&](std::size_t i) { w.number(f[i].t); });
  if (!a.s.empty()) w.member("s").scalars(n, [&](std::size_t i) { w.number(a.s[i]); });
  w.member("points").containers(n, [&](std::size_t i) { w.vec(f[i].position); });
  w.member("frames").begin_object();
  w.member("T").containers(n, [&](std::size_t i) { w.vec(f[i].tangent, f[i].tangent_defined); });
  w.member("N").containers(n, [&](std::size_t i) { w.vec(f[i].normal, f[i].frame_defined); });
  w.member("B").containers(n, [&](std::size_t i) { w.vec(f[i].binormal, f[i].frame_defined); });
  w.end_object();
  w.member("curvature").scalars(n, [&](std::size_t i) { w.number_or_null(f[i].curvature, f[i].tangent_defined); });
  w.member("torsion").scalars(n, [&](std::size_t i) { w.number_or_null(f[i].torsion, f[i].torsion_defined); });
  w.member("curvature_derivative").scalars(n, [&](std::size_t i) {
    w.number_or_null(f[i].curvature_derivative, f[i].frame_defined);
  });
  w.member("speed").scalars(
      n, [&](std::size_t i) { w.number_or_null(f[i].speed, f[i].reason != diffgeom::Undefined::NonFinite); });
  if (!a.bishop.empty()) {
    w.member("bishop").begin_object();
    w.member("U").containers(n, [&](std::size_t i) { w.vec(a.bishop[i].u, a.bishop[i].defined); });
    w.member("V").containers(n, [&](std::size_t i) { w.vec(a.bishop[i].v, a.bishop[i].defined); });
    w.end_object();
  }
  w.member("fins").containers(a.fins.size(), [&](std::size_t k) {
    const diffgeom::AnalysedFins& comb = a.fins[k];
    const diffgeom::Fins& fins = comb.fins;
    w.begin_object().member("kind").string(diffgeom::fin_kind_name(comb.kind)).member("scale").number(comb.scale);
    w.member("t").scalars(fins.t.size(), [&](std::size_t i) { w.number(fins.t[i]); });
    w.member("base").containers(fins.t.size(), [&](std::size_t i) { w.vec(fins.base[i]); });
    w.member("tip").containers(fins.t.size(), [&](std::size_t i) { w.vec(fins.tip[i], fins.defined[i] != 0); });
    w.end_object();
  });
  w.member("planarity").value(planarity_to_json(a.planarity));
  if (a.features) {
    w.member("features");
    write_features(w, *a.features);
  }
}

std::string curve_analysis_json(const diffgeom::CurveAnalysis& a, bool pretty, std::optional<std::uint64_t> revision) {
  std::string text;
  // About 420 bytes per sample and 230 per fin, most of it numbers of up to 24 characters.
  std::size_t fins = 0;
  for (const auto& comb : a.fins) fins += comb.fins.t.size();
  text.reserve(512 + a.samples.size() * (pretty ? 560 : 420) + fins * 230);
  JsonText w(text, pretty);
  w.begin_object();
  write_curve_analysis_members(w, a);
  if (revision) w.member("revision").integer(static_cast<long long>(*revision));
  w.end_object();
  if (pretty) text += '\n';
  return text;
}

}  // namespace hula::io

namespace hula::io {

diffgeom::AnalysisOptions analysis_request_defaults() {
  diffgeom::AnalysisOptions o;
  o.samples = 100;
  o.features = true;
  return o;
}

std::string analyse_curve_json(const curve::Curve& curve, const diffgeom::AnalysisOptions& options, bool pretty,
                               std::optional<std::uint64_t> revision) {
  return curve_analysis_json(diffgeom::analyse_curve(curve, options), pretty, revision);
}

}  // namespace hula::io
