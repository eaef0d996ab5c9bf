// SPDX-License-Identifier: MIT
// Unit tests of the curve analysis codec (io/curve_analysis_json.hpp): the JSON text it writes, parsed
// back, against diffgeom's own results on the same curve, double for double; the request reader.

#include "hula/io/curve_analysis_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hula/diffgeom/analysis.hpp"
#include "hula/nurbs/interpolate.hpp"

namespace hula::io {

using json::Json;
namespace {

// The bench's curve: 50 points of a space wave (z = cos(i / 7): not planar), interpolated.
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
TEST(CurveAnalysisJson, TextReadsBackToDiffgeomResults) {
  const nurbs::NurbsCurve c = wave();
  diffgeom::AnalysisOptions request = analysis_request_defaults();
  request.fins = {diffgeom::FinKind::Curvature, diffgeom::FinKind::Torsion};
  request.fin_scale = 0.5;
  const Json out = Json::parse(analyse_curve_json(c, request, false, 42));
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

  // The wave is not planar (z = cos(i/7)): no inflection, by the one rule.
  EXPECT_FALSE(out["planarity"]["planar"].get<bool>());
  const std::vector<diffgeom::Feature> inflections;
  ASSERT_EQ(out["features"]["inflections"].size(), inflections.size());
  for (std::size_t i = 0; i < inflections.size(); ++i) {
    EXPECT_EQ(out["features"]["inflections"][i]["t"].get<double>(), inflections[i].t);
    expect_vec(out["features"]["inflections"][i]["point"], inflections[i].position, "inflection");
  }
  const auto extrema = diffgeom::curvature_extrema(c);
  ASSERT_EQ(out["features"]["curvature_extrema"].size(), extrema.size());
  for (std::size_t i = 0; i < extrema.size(); ++i) {
    const Json& e = out["features"]["curvature_extrema"][i];
    EXPECT_EQ(e["kind"], std::string(extremum_kind_name(extrema[i].kind)));
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
    EXPECT_EQ(k["curvature_left"].get<double>(), knots[i].curvature_left);
    if (std::isfinite(knots[i].tangent_angle)) {
      EXPECT_EQ(k["tangent_angle"].get<double>(), knots[i].tangent_angle);
    }
  }
}

// checks a straight line's undefined frames, curvature fins of length 0 and the absent features are
// written as JSON null / left out, integral numbers keep a ".0" as nlohmann writes them
TEST(CurveAnalysisJson, UndefinedValuesAreNullAndFeaturesCanBeLeftOut) {
  const std::vector<Vec3> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  diffgeom::AnalysisOptions request;
  request.samples = 4;
  request.features = false;
  request.fins = {diffgeom::FinKind::Normal};
  const std::string text = analyse_curve_json(nurbs::interpolate_cubic(line), request, false, 3);
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

// checks that the CLI's layout and the compact text read back to the same JSON value, bit for bit, and that
// the layout is format_json's (a column of numbers on one line, one member per line)
TEST(CurveAnalysisJson, PrettyAndCompactTextsAreOneValue) {
  diffgeom::AnalysisOptions o;
  o.samples = 7;
  o.features = true;
  o.bishop = true;
  o.arc_lengths = true;
  o.fins = {diffgeom::FinKind::Curvature};
  const diffgeom::CurveAnalysis a = diffgeom::analyse_curve(wave(), o);
  const std::string pretty = curve_analysis_json(a, true);
  const Json value = Json::parse(curve_analysis_json(a, false));
  EXPECT_EQ(Json::parse(pretty), value);
  EXPECT_NE(pretty.find("\n  \"t\": [0.0, "), std::string::npos) << pretty.substr(0, 200);
  EXPECT_NE(pretty.find("\n  \"frames\": {\n    \"T\": [\n      ["), std::string::npos) << pretty.substr(0, 400);
}

// checks the request reader: defaults kept, members read, unknown members and bad values refused naming them
TEST(CurveAnalysisJson, ReadsRequestsAndNamesBadMembers) {
  const diffgeom::AnalysisOptions d = analysis_request_defaults();
  EXPECT_EQ(d.samples, 100);
  EXPECT_TRUE(d.features);
  const diffgeom::AnalysisOptions o = analysis_options_from_json(
      Json::parse(R"({"samples": 9, "by": "arclength", "fins": ["torsion", "bishop-u"], "scale": 2,
                      "fin_density": 30, "features": false, "bishop": true, "arc_lengths": true, "at": [0, 1]})"),
      d);
  EXPECT_EQ(o.samples, 9);
  EXPECT_EQ(o.by, diffgeom::SampleBy::ArcLength);
  EXPECT_EQ(o.fins, (std::vector<diffgeom::FinKind>{diffgeom::FinKind::Torsion, diffgeom::FinKind::BishopU}));
  EXPECT_EQ(o.fin_scale, 2.0);
  EXPECT_EQ(o.fin_density, 30);
  EXPECT_FALSE(o.features);
  EXPECT_TRUE(o.bishop && o.arc_lengths);
  EXPECT_EQ(o.at, (std::vector<double>{0, 1}));
  const auto field_of = [&](const char* text) {
    try {
      (void)analysis_options_from_json(Json::parse(text), d);
    } catch (const Error& e) {
      return e.where().field;
    }
    return std::string("accepted");
  };
  EXPECT_EQ(field_of(R"({"colour": 1})"), "colour");
  EXPECT_EQ(field_of(R"({"by": "speed"})"), "by");
  EXPECT_EQ(field_of(R"({"fins": ["tosion"]})"), "fins");
  EXPECT_EQ(field_of(R"({"scale": 0})"), "scale");
  EXPECT_EQ(field_of(R"({"samples": 0})"), "samples");
  EXPECT_EQ(field_of(R"({"features": 1})"), "features");
}

}  // namespace
}  // namespace hula::io
