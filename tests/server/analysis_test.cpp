// SPDX-License-Identifier: MIT
// Unit tests of the viewport analysis (server/analysis.hpp): the JSON text it writes, parsed back,
// against diffgeom's own results on the same curve, double for double.
#include "hula/server/analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hula/diffgeom/continuity.hpp"
#include "hula/diffgeom/features.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/nurbs/interpolate.hpp"

namespace hula::server {
namespace {

// The bench's curve: 50 points of a planar-ish wave, interpolated (inflections and extrema).
nurbs::NurbsCurve wave() {
  std::vector<Vec3> points;
  for (int i = 0; i < 50; ++i) points.push_back({double(i), std::sin(i / 5.0) * 3, std::cos(i / 7.0)});
  return nurbs::interpolate_cubic(points);
}

void expect_vec(const Json& j, const Vec3& v, const std::string& what) {
  ASSERT_TRUE(j.is_array()) << what << ": " << j.dump();
  EXPECT_EQ(j[0].get<double>(), v.x) << what;
  EXPECT_EQ(j[1].get<double>(), v.y) << what;
  EXPECT_EQ(j[2].get<double>(), v.z) << what;
}

// checks every column, the curvature comb and the features of the text read back bit for bit equal
// to diffgeom::frenet, diffgeom::fins, inflections, curvature_extrema and knot_continuity
TEST(Analysis, TextReadsBackToDiffgeomResults) {
  const nurbs::NurbsCurve c = wave();
  AnalysisRequest request;
  request.samples = 100;
  request.fins = {diffgeom::FinKind::Curvature, diffgeom::FinKind::Torsion};
  request.scale = 0.5;
  const Json out = Json::parse(analysis_json(c, request, 42));
  EXPECT_EQ(out["revision"].get<std::uint64_t>(), 42u);

  std::vector<double> ts(100);
  for (std::size_t i = 0; i < ts.size(); ++i)
    ts[i] = i + 1 == ts.size() ? c.domain().end : c.domain().start + c.domain().length() * double(i) / 99.0;
  std::vector<diffgeom::FrenetPoint> f(ts.size());
  diffgeom::frenet(c, ts, f);
  ASSERT_EQ(out["t"].size(), 100u);
  for (std::size_t i = 0; i < f.size(); ++i) {
    const std::string at = "sample " + std::to_string(i);
    EXPECT_EQ(out["t"][i].get<double>(), f[i].t) << at;
    expect_vec(out["points"][i], f[i].position, at);
    ASSERT_TRUE(f[i].tangent_defined) << at;
    expect_vec(out["frames"]["T"][i], f[i].tangent, at);
    EXPECT_EQ(out["curvature"][i].get<double>(), f[i].curvature) << at;
    EXPECT_EQ(out["speed"][i].get<double>(), f[i].speed) << at;
    if (f[i].frame_defined) {
      expect_vec(out["frames"]["N"][i], f[i].normal, at);
      expect_vec(out["frames"]["B"][i], f[i].binormal, at);
    } else {
      EXPECT_TRUE(out["frames"]["N"][i].is_null()) << at;
      EXPECT_TRUE(out["frames"]["B"][i].is_null()) << at;
    }
    if (f[i].torsion_defined) {
      EXPECT_EQ(out["torsion"][i].get<double>(), f[i].torsion) << at;
    } else {
      EXPECT_TRUE(out["torsion"][i].is_null()) << at;
    }
  }

  ASSERT_EQ(out["fins"].size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    diffgeom::FinOptions o;
    o.kind = request.fins[k];
    o.scale = 0.5;
    o.density = 100;
    const diffgeom::Fins fins = diffgeom::fins(c, o);
    const Json& comb = out["fins"][k];
    EXPECT_EQ(comb["kind"], std::string(diffgeom::fin_kind_name(o.kind)));
    ASSERT_EQ(comb["tip"].size(), fins.tip.size());
    for (std::size_t i = 0; i < fins.tip.size(); ++i) {
      EXPECT_EQ(comb["t"][i].get<double>(), fins.t[i]);
      expect_vec(comb["base"][i], fins.base[i], "fin base " + std::to_string(i));
      if (fins.defined[i]) {
        expect_vec(comb["tip"][i], fins.tip[i], "fin tip " + std::to_string(i));
      } else {
        EXPECT_TRUE(comb["tip"][i].is_null());
      }
    }
  }

  const auto inflections = diffgeom::inflections(c);
  ASSERT_FALSE(inflections.empty());
  ASSERT_EQ(out["features"]["inflections"].size(), inflections.size());
  for (std::size_t i = 0; i < inflections.size(); ++i) {
    EXPECT_EQ(out["features"]["inflections"][i]["t"].get<double>(), inflections[i].t);
    expect_vec(out["features"]["inflections"][i]["point"], inflections[i].position, "inflection");
  }
  const auto extrema = diffgeom::curvature_extrema(c);
  ASSERT_EQ(out["features"]["curvature_extrema"].size(), extrema.size());
  for (std::size_t i = 0; i < extrema.size(); ++i) {
    const Json& e = out["features"]["curvature_extrema"][i];
    EXPECT_EQ(e["kind"], std::string(diffgeom::feature_kind_name(extrema[i].kind)));
    EXPECT_EQ(e["t"].get<double>(), extrema[i].t);
    EXPECT_EQ(e["curvature"].get<double>(), extrema[i].curvature);
  }
  const auto knots = diffgeom::knot_continuity(c);
  ASSERT_EQ(out["features"]["knots"].size(), knots.size());
  for (std::size_t i = 0; i < knots.size(); ++i) {
    const Json& k = out["features"]["knots"][i];
    EXPECT_EQ(k["t"].get<double>(), knots[i].t);
    EXPECT_EQ(k["multiplicity"].get<int>(), knots[i].multiplicity);
    EXPECT_EQ(k["parametric"].get<int>(), knots[i].parametric);
    EXPECT_EQ(k["geometric"].get<int>(), knots[i].geometric);
    if (std::isfinite(knots[i].tangent_angle)) {
      EXPECT_EQ(k["tangent_angle"].get<double>(), knots[i].tangent_angle);
    }
  }
}

// checks a straight line's undefined frames, curvature fins of length 0 and the absent features are
// written as JSON null / left out, integral numbers keep a ".0" as nlohmann writes them
TEST(Analysis, UndefinedValuesAreNullAndFeaturesCanBeLeftOut) {
  const std::vector<Vec3> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  AnalysisRequest request;
  request.samples = 4;
  request.features = false;
  request.fins = {diffgeom::FinKind::Normal};
  const std::string text = analysis_json(nurbs::interpolate_cubic(line), request, 3);
  const Json out = Json::parse(text);
  EXPECT_FALSE(out.contains("features"));
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_TRUE(out["frames"]["N"][i].is_null());
    EXPECT_TRUE(out["torsion"][i].is_null());
    EXPECT_TRUE(out["fins"][0]["tip"][i].is_null());
    EXPECT_EQ(out["curvature"][i].get<double>(), 0.0);
  }
  EXPECT_NE(text.find("\"t\":[0.0,"), std::string::npos) << text.substr(0, 80);
}

}  // namespace
}  // namespace hula::server
