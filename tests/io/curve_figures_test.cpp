// SPDX-License-Identifier: MIT
#include "hula/io/curve_figures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "hula/io/json_curve.hpp"
#include "hula/testing/expect_error.hpp"

namespace {

using hula::Errc;
using hula::diffgeom::FinKind;
using namespace hula::io;

// A circle of radius 2 about the origin in the plane z = 0, exactly from its law.
hula::curve::Curve circle() {
  return parse_curve_json(
      R"json({"kind": "law", "expression": "vec(2*cos(t), 2*sin(t), 0)", "parameter": "t",
              "domain": [0, 6.283185307179586]})json");
}

// checks the automatic curvature fin scale against its closed form on a circle of radius 2 (the
// longest fin a fifth of the box diagonal 4√2, κ = 1/2) and every tip at distance 2 + s κ from the
// centre (P − sκN points away from the centre)
TEST(CurveFigures, CircleCurvatureFinsHaveTheDocumentedScale) {
  CurveFigureOptions o;
  o.fins = {FinKind::Curvature};
  const CurveFigures f = curve_figures(circle(), o);
  ASSERT_EQ(f.fins.size(), 1u);
  // The rule (diffgeom::auto_fin_scale) on the fins' own samples: a fifth of their box diagonal over κ = 1/2.
  hula::Box3 box;
  for (const hula::Vec3& p : f.fins[0].fins.base) box.add(p);
  const double longest = 0.2 * box.diagonal();
  EXPECT_NEAR(box.diagonal(), 4.0 * std::numbers::sqrt2, 1e-2);
  EXPECT_NEAR(f.fins[0].scale, longest / 0.5, 1e-9);
  ASSERT_EQ(f.fins[0].fins.tip.size(), 120u);
  for (std::size_t i = 0; i < f.fins[0].fins.tip.size(); ++i)
    EXPECT_NEAR(hula::norm(f.fins[0].fins.tip[i]), 2.0 + longest, 1e-9) << i;
  EXPECT_EQ(f.view, CurveView::Xy);
  EXPECT_EQ(f.view_description, "XY, seen from +Z");
}

// checks the curve figure names its view, legends each fin kind with its scale, and the six figures
// are complete SVG documents drawn by io::SvgFigure
TEST(CurveFigures, FiguresCarryTitleViewAndFinLegends) {
  CurveFigureOptions o;
  o.fins = {FinKind::Curvature, FinKind::BishopU};
  o.fin_scale = 0.25;
  const CurveFigures f = curve_figures(circle(), o);
  ASSERT_EQ(f.figures.size(), 6u);
  const char* names[] = {"curve", "kappa", "tau", "radius", "speed", "logcurvature"};
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(f.figures[i].name, names[i]);
    const std::string svg = f.figures[i].figure.render();
    EXPECT_EQ(svg.rfind("</svg>\n"), svg.size() - 7) << names[i];
  }
  const std::string curve = f.figures[0].figure.render();
  EXPECT_NE(curve.find("curve (XY, seen from +Z) with curvature, bishop-u fins"), std::string::npos) << curve;
  EXPECT_NE(curve.find("curvature fins P - s\u03BAN, s = 0.25"), std::string::npos);
  EXPECT_NE(curve.find("Bishop fins P - sU, s = 0.25"), std::string::npos);
  // The Bishop fins are unit vectors times s: each tip 0.25 from its base.
  for (std::size_t i = 0; i < f.fins[1].fins.tip.size(); ++i)
    EXPECT_NEAR(hula::norm(f.fins[1].fins.tip[i] - f.fins[1].fins.base[i]), 0.25, 1e-12) << i;
}

// checks the automatic view follows the curve's plane (x = const → YZ, y = const → ZX), a helix gets
// the oblique view, and an explicit view is kept
TEST(CurveFigures, AutoViewFollowsThePlane) {
  const auto in_yz = parse_curve_json(
      R"json({"kind": "law", "expression": "vec(1, cos(t), sin(t))", "parameter": "t", "domain": [0, 3]})json");
  EXPECT_EQ(curve_figures(in_yz).view, CurveView::Yz);
  const auto in_zx = parse_curve_json(
      R"json({"kind": "law", "expression": "vec(cos(t), -2, sin(t))", "parameter": "t", "domain": [0, 3]})json");
  EXPECT_EQ(curve_figures(in_zx).view, CurveView::Zx);
  const auto helix = parse_curve_json(
      R"json({"kind": "law", "expression": "vec(cos(t), sin(t), 0.5*t)", "parameter": "t", "domain": [0, 12]})json");
  const CurveFigures h = curve_figures(helix);
  EXPECT_EQ(h.view, CurveView::Auto);
  EXPECT_EQ(h.view_description, "seen from -Y, 20 degrees above");
  CurveFigureOptions o;
  o.view = CurveView::Isometric;
  EXPECT_EQ(curve_figures(helix, o).view_description, "isometric, seen from (1, 1, 1)");
}

// checks the automatic scale of the Combescure fins (thesis 8.3 eq. 44) on the helix (2 cos t, 2 sin t,
// 0.5 t): τ/κ = 1/4, so with the automatic scale s every fin is the same vertical segment
// s (0, 0, √(1 + 1/16)) (closed form), and "combescure" parses as a fin kind
TEST(CurveFigures, HelixCombescureFinsAreEqualVerticalSegments) {
  CurveFigureOptions o;
  o.fins = parse_fin_kinds("combescure");
  ASSERT_EQ(o.fins, std::vector<FinKind>{FinKind::Combescure});
  const CurveFigures f = curve_figures(
      parse_curve_json(R"json({"kind": "law", "expression": "vec(2*cos(t), 2*sin(t), 0.5*t)", "parameter": "t",
                               "domain": [0, 6]})json"),
      o);
  ASSERT_EQ(f.fins.size(), 1u);
  const double length = f.fins[0].scale * std::sqrt(1.0 + 1.0 / 16.0);
  EXPECT_GT(length, 0.0);
  const hula::diffgeom::Fins& c = f.fins[0].fins;
  for (std::size_t i = 0; i < c.tip.size(); ++i) {
    EXPECT_NEAR(hula::norm(c.tip[i] - c.base[i] - hula::Vec3{0.0, 0.0, length}), 0.0, 1e-9) << i;
  }
}

// checks the fin list and view parsers name the entry at fault and the allowed names, and the
// options name their bad field
TEST(CurveFigures, BadNamesAndOptionsAreNamed) {
  const auto kinds = parse_fin_kinds("torsion,bishop,torsion");
  ASSERT_EQ(kinds.size(), 3u);
  EXPECT_EQ(kinds[0], FinKind::Torsion);
  EXPECT_EQ(kinds[1], FinKind::BishopU);
  EXPECT_EQ(kinds[2], FinKind::BishopV);
  HULA_EXPECT_ERROR((void)parse_fin_kinds("curvature,tosion", "--fins"), Errc::InvalidOption, "--fins[1] = 'tosion'");
  HULA_EXPECT_ERROR((void)parse_curve_view("top", "--view"), Errc::InvalidOption, "--view = 'top'");
  CurveFigureOptions o;
  o.fin_density = 1;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "fin_density = 1");
  o = {};
  o.fin_scale = std::nan("");
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "fin_scale");
}

}  // namespace
