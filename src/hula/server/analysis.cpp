// SPDX-License-Identifier: MIT
// The viewport analysis of a curve (analysis.hpp).
#include "hula/server/analysis.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <span>
#include <string_view>

#include "hula/diffgeom/continuity.hpp"
#include "hula/diffgeom/features.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/io/json_read.hpp"
#include "hula/nurbs/arc_length.hpp"

namespace hula::server {

namespace {

namespace json = io::json;

diffgeom::FinKind fin_kind(const std::string& name, std::size_t index) {
  if (const std::optional<diffgeom::FinKind> k = diffgeom::fin_kind_from_name(name)) return *k;
  throw Error(Errc::InvalidOption,
              "fins[" + std::to_string(index) + "] = \"" + name +
                  "\" is not a fin (curvature, torsion, normal, binormal, bishop-u, bishop-v, combescure)",
              ErrorWhere{.field = "fins", .index = index});
}

}  // namespace

AnalysisRequest analysis_request_from_json(const Json& body) {
  const json::JsonPath root;
  json::reject_unknown_members(body, root, {"samples", "by", "fins", "scale", "features"});
  AnalysisRequest r;
  if (const Json* n = json::optional_member(body, "samples"))
    r.samples = static_cast<int>(json::get_integer(*n, json::root_path("samples"), 2, 100000));
  if (const Json* by = json::optional_member(body, "by")) {
    const std::string b = json::get_string(*by, json::root_path("by"));
    if (b == "parameter")
      r.by = SampleBy::Parameter;
    else if (b == "arclength")
      r.by = SampleBy::ArcLength;
    else
      throw Error(Errc::InvalidOption, "by = \"" + b + "\" is not \"parameter\" or \"arclength\"",
                  ErrorWhere{.field = "by"});
  }
  if (const Json* fins = json::optional_member(body, "fins")) {
    const Json& list = json::get_array(*fins, json::root_path("fins"));
    for (std::size_t i = 0; i < list.size(); ++i)
      r.fins.push_back(fin_kind(json::get_string(list[i], json::root_path("fins").element(i)), i));
  }
  if (const Json* s = json::optional_member(body, "scale")) r.scale = json::get_number(*s, json::root_path("scale"));
  if (const Json* f = json::optional_member(body, "features")) {
    if (!f->is_boolean()) json::type_error(*f, json::root_path("features"), "true or false");
    r.features = f->get<bool>();
  }
  return r;
}

namespace {

// The response is written as text, column by column, into one buffer: a JSON tree of its ~3,000
// numbers cost a node and often a vector per value (a third of the request's CPU time in a perf
// profile, docs/benchmarks.md). Numbers are the shortest text that reads back to the same double
// (std::to_chars), with ".0" on integral values as nlohmann writes them; non-finite ones are null.
class Writer {
 public:
  explicit Writer(std::string& out) : out_(out) {}

  Writer& raw(std::string_view text) {
    out_ += text;
    return *this;
  }
  Writer& number(double v) {
    if (!std::isfinite(v)) return raw("null");
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    const std::string_view text(buffer, static_cast<std::size_t>(end - buffer));
    out_ += text;
    if (text.find_first_of(".e") == std::string_view::npos) out_ += ".0";
    return *this;
  }
  Writer& integer(long long v) {
    char buffer[24];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    out_.append(buffer, end);
    return *this;
  }
  // [x,y,z], or null when a coordinate is not finite.
  Writer& vec(const Vec3& v) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return raw("null");
    raw("[").number(v.x).raw(",").number(v.y).raw(",").number(v.z);
    return raw("]");
  }
  // [f(0),...,f(n-1)], where f writes one element.
  template <class F>
  Writer& array(std::size_t n, F&& element) {
    raw("[");
    for (std::size_t i = 0; i < n; ++i) {
      if (i > 0) raw(",");
      element(i);
    }
    return raw("]");
  }

 private:
  std::string& out_;
};

// The frames' columns: one array per quantity, with null where it is undefined.
void write_columns(Writer& w, std::span<const diffgeom::FrenetPoint> f) {
  const std::size_t n = f.size();
  w.raw("\"t\":").array(n, [&](std::size_t i) { w.number(f[i].t); });
  w.raw(",\"points\":").array(n, [&](std::size_t i) { w.vec(f[i].position); });
  w.raw(",\"frames\":{\"T\":").array(n, [&](std::size_t i) {
    f[i].tangent_defined ? w.vec(f[i].tangent) : w.raw("null");
  });
  w.raw(",\"N\":").array(n, [&](std::size_t i) { f[i].frame_defined ? w.vec(f[i].normal) : w.raw("null"); });
  w.raw(",\"B\":").array(n, [&](std::size_t i) { f[i].frame_defined ? w.vec(f[i].binormal) : w.raw("null"); });
  w.raw("},\"curvature\":").array(n, [&](std::size_t i) {
    f[i].tangent_defined ? w.number(f[i].curvature) : w.raw("null");
  });
  w.raw(",\"torsion\":").array(n, [&](std::size_t i) {
    f[i].torsion_defined ? w.number(f[i].torsion) : w.raw("null");
  });
  w.raw(",\"speed\":").array(n, [&](std::size_t i) { w.number(f[i].speed); });
}

}  // namespace

std::string analysis_json(const curve::Curve& subject, const AnalysisRequest& request, std::uint64_t revision) {
  const nurbs::NurbsCurve& curve = subject.nurbs();
  const auto n = static_cast<std::size_t>(request.samples);
  const nurbs::Interval domain = curve.domain();
  std::vector<double> ts(n);
  // A natural curve's parameter is its arc length: both samplings are the same.
  const bool natural = subject.natural_evaluator() != nullptr;
  if (request.by == SampleBy::Parameter || natural) {
    for (std::size_t i = 0; i < n; ++i)
      ts[i] = i + 1 == n ? domain.end
                         : domain.start + domain.length() * static_cast<double>(i) / static_cast<double>(n - 1);
  } else {
    const double length = nurbs::arc_length(curve);
    for (std::size_t i = 0; i < n; ++i)
      ts[i] = i == 0 ? domain.start
              : i + 1 == n
                  ? domain.end
                  : nurbs::parameter_at_length(curve, length * static_cast<double>(i) / static_cast<double>(n - 1));
  }
  std::vector<diffgeom::FrenetPoint> frames(n);
  // A natural curve is analysed exactly (κ and τ from its laws).
  if (natural)
    diffgeom::frenet(subject, ts, frames);
  else
    diffgeom::frenet(curve, ts, frames);

  std::string text;
  // About 560 bytes per sample with one comb, most of it numbers of up to 24 characters.
  text.reserve(256 + n * (330 + 230 * request.fins.size()));
  Writer w(text);
  w.raw("{");
  write_columns(w, frames);
  w.raw(",\"fins\":").array(request.fins.size(), [&](std::size_t k) {
    diffgeom::FinOptions o;
    o.kind = request.fins[k];
    o.scale = request.scale;
    o.density = request.samples;
    // A law curve's fins are exact from its law. Otherwise, sampled by parameter, the fins stand at the
    // samples: they are built from the frames already evaluated there (the same parameters, bit for bit)
    // instead of evaluating them again.
    const diffgeom::Fins f = subject.law() != nullptr || natural ? diffgeom::fins(subject, o)
                             : request.by == SampleBy::Parameter ? diffgeom::fins(frames, o)
                                                                 : diffgeom::fins(curve, o);
    w.raw("{\"kind\":\"").raw(diffgeom::fin_kind_name(o.kind)).raw("\",\"t\":");
    w.array(f.t.size(), [&](std::size_t i) { w.number(f.t[i]); });
    w.raw(",\"base\":").array(f.t.size(), [&](std::size_t i) { w.vec(f.base[i]); });
    w.raw(",\"tip\":").array(f.t.size(), [&](std::size_t i) { f.defined[i] ? w.vec(f.tip[i]) : w.raw("null"); });
    w.raw("}");
  });
  if (request.features) {
    const std::vector<diffgeom::Feature> inflections =
        natural ? diffgeom::inflections(subject) : diffgeom::inflections(curve);
    w.raw(",\"features\":{\"inflections\":").array(inflections.size(), [&](std::size_t i) {
      w.raw("{\"t\":").number(inflections[i].t).raw(",\"point\":").vec(inflections[i].position).raw("}");
    });
    const std::vector<diffgeom::Feature> extrema =
        natural ? diffgeom::curvature_extrema(subject) : diffgeom::curvature_extrema(curve);
    w.raw(",\"curvature_extrema\":").array(extrema.size(), [&](std::size_t i) {
      const diffgeom::Feature& f = extrema[i];
      w.raw("{\"kind\":\"").raw(diffgeom::feature_kind_name(f.kind)).raw("\",\"t\":").number(f.t);
      w.raw(",\"point\":").vec(f.position).raw(",\"curvature\":").number(f.curvature).raw("}");
    });
    const std::vector<diffgeom::Continuity> knots = diffgeom::knot_continuity(curve);
    w.raw(",\"knots\":").array(knots.size(), [&](std::size_t i) {
      const diffgeom::Continuity& c = knots[i];
      w.raw("{\"t\":").number(c.t).raw(",\"multiplicity\":").integer(c.multiplicity);
      w.raw(",\"parametric\":").integer(c.parametric).raw(",\"geometric\":").integer(c.geometric);
      w.raw(",\"tangent_angle\":").number(c.tangent_angle).raw("}");
    });
    w.raw("}");
  }
  w.raw(",\"revision\":").integer(static_cast<long long>(revision)).raw("}");
  return text;
}

}  // namespace hula::server
