// SPDX-License-Identifier: MIT
// `hula offset` run as a process: its JSON is the library's answer through the
// io codec, bit for bit (diffgeom::planar_offset, then
// io::planar_offset_to_json); the written curve files are the raw offset (a
// law curve for a law input, on the concentric circle) and the trimmed offset
// (every point at the offset distance from the parabola, closed form); bad
// command lines are refused naming the option.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hula/io/json_curve.hpp"
#include "hula/io/offset_json.hpp"
#include "hula/nurbs/bezier.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/testing/process_json.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif

namespace hula {
namespace {

using nlohmann::json;

json members_of(json doc, std::initializer_list<const char*> drop) {
  for (const char* key : drop) doc.erase(key);
  return doc;
}

nurbs::NurbsCurve parabola() {
  const std::vector<Vec3> P = {{-1, 1, 0}, {0, -1, 0}, {1, 1, 0}};
  return nurbs::make_bezier(P, {}, 2);
}

// checks: the printed answer is the library's through the codec; -o writes the trimmed offset, whose points lie
// 1 from the parabola y = x² (closest points on the parabola, closed-form curve).
TEST(OffsetCli, ParabolaIsTheLibraryAnswerAndTrimmedFileIsAtDistance) {
  testing::TempDir dir;
  const std::string in = (dir / "parabola.json").string();
  const std::string out = (dir / "offset.json").string();
  io::write_curve_file(in, parabola());
  const json doc = testing::stdout_json(
      testing::run_process(HULA_CLI_PATH, {"offset", in, "--distance", "1", "--tolerance", "1e-9", "-o", out}));
  diffgeom::OffsetOptions o;
  o.tolerance = 1e-9;
  EXPECT_EQ(members_of(doc, {"curve", "output"}), io::offset_answer(curve::Curve(parabola()), 1.0, o));
  EXPECT_EQ(doc["cusps"].size(), 2U);
  ASSERT_EQ(doc["loops"].size(), 1U);
  EXPECT_NEAR(doc["loops"][0]["point"][1].get<double>(), 1.25, 1e-9);
  const curve::Curve trimmed = io::read_curve_file(out);
  const Interval d = trimmed.domain();
  for (int i = 0; i <= 200; ++i) {
    const Vec3 p = trimmed.point(d.start + (d.end - d.start) * i / 200.0);
    EXPECT_NEAR(nurbs::closest_point(parabola(), p).distance, 1.0, 1e-8);
  }
}

// checks: --raw writes the raw offset of a law circle as a law curve, on the circle of radius 1.5 (closed form);
// a negative distance given as --distance=-1 offsets outwards.
TEST(OffsetCli, RawOffsetOfLawIsALawCurve) {
  testing::TempDir dir;
  const std::string in = (dir / "circle.json").string();
  const std::string out = (dir / "raw.json").string();
  io::write_curve_file(in, curve::Curve::from_law("vec(2*cos(t), 2*sin(t))", "t", {0.0, 6.283185307179586}));
  const json doc = testing::stdout_json(
      testing::run_process(HULA_CLI_PATH, {"offset", in, "--distance", "0.5", "-o", out, "--raw"}));
  EXPECT_EQ(doc["exact"], true);
  const curve::Curve raw = io::read_curve_file(out);
  EXPECT_EQ(raw.kind(), curve::Kind::Law);
  EXPECT_NEAR(norm(raw.point(1.0)), 1.5, 1e-14);
  const json outward = testing::stdout_json(testing::run_process(HULA_CLI_PATH, {"offset", in, "--distance=-1"}));
  EXPECT_NEAR(norm(io::curve_from_json(outward["raw"]).point(1.0)), 3.0, 1e-14);
}

// checks: a missing distance, a tolerance out of range, a space curve and -o with several pieces (the two lobes of a
// peanut offset inwards past its waist) are refused.
TEST(OffsetCli, RefusesBadCommandLines) {
  testing::TempDir dir;
  const std::string in = (dir / "parabola.json").string();
  io::write_curve_file(in, parabola());
  EXPECT_EQ(testing::run_process(HULA_CLI_PATH, {"offset", in}).exit_code, 2);
  const testing::ProcessResult tol =
      testing::run_process(HULA_CLI_PATH, {"offset", in, "--distance", "1", "--tolerance", "1"});
  EXPECT_EQ(tol.exit_code, 2);
  EXPECT_NE(tol.err.find("--tolerance"), std::string::npos) << tol.err;
  const std::string helix = (dir / "helix.json").string();
  io::write_curve_file(helix, curve::Curve::from_law("vec(cos(t), sin(t), t)", "t", {0.0, 1.0}));
  const testing::ProcessResult space = testing::run_process(HULA_CLI_PATH, {"offset", helix, "--distance", "1"});
  EXPECT_EQ(space.exit_code, 3);
  EXPECT_EQ(testing::stderr_error(space)["where"]["field"], "curve");
  // A peanut (two lobes joined by a waist 0.5 wide) offset inwards by 0.35 splits into one closed piece per lobe:
  // -o cannot write them as one curve file.
  const std::string peanut = (dir / "peanut.json").string();
  io::write_curve_file(
      peanut, curve::Curve::from_law("vec(2*cos(t), sin(t)*(0.25 + cos(t)^2))", "t", {0.0, 6.283185307179586}));
  const json pieces =
      testing::stdout_json(testing::run_process(HULA_CLI_PATH, {"offset", peanut, "--distance", "0.35"}));
  ASSERT_EQ(pieces["trimmed"].size(), 2U);
  for (const json& piece : pieces["trimmed"]) EXPECT_EQ(piece["closed"], true);
  const testing::ProcessResult many =
      testing::run_process(HULA_CLI_PATH, {"offset", peanut, "--distance", "0.35", "-o", (dir / "many.json").string()});
  EXPECT_EQ(many.exit_code, 3);
  EXPECT_EQ(testing::stderr_error(many)["where"]["field"], "output");
}

// checks: `hula helical-offset` writes the library's curve (a law curve for a law circle, on the toroidal helix
// ((2 − 0.5 cos 8t) cos t, (2 − 0.5 cos 8t) sin t, 0.5 sin 8t), closed form) and prints the codec's summary; a bad
// frame name exits 3 naming "frame".
TEST(OffsetCli, HelicalOffsetWritesTheToroidalHelix) {
  testing::TempDir dir;
  const std::string in = (dir / "circle.json").string();
  const std::string out = (dir / "helix.json").string();
  const curve::Curve circle = curve::Curve::from_law("vec(2*cos(t), 2*sin(t))", "t", {0.0, 6.283185307179586});
  io::write_curve_file(in, circle);
  const json doc = testing::stdout_json(
      testing::run_process(HULA_CLI_PATH, {"helical-offset", in, "--distance", "0.5", "--twist", "8*t", "-o", out}));
  json want = io::helical_offset_answer(circle, "0.5", "8*t");
  want.erase("curve");
  EXPECT_EQ(members_of(doc, {"input", "output"}), want);
  const curve::Curve h = io::read_curve_file(out);
  EXPECT_EQ(h.kind(), curve::Kind::Law);
  for (double t : {0.0, 0.7, 2.5}) {
    const double rho = 2 - 0.5 * std::cos(8 * t);
    EXPECT_LE(norm(h.point(t) - Vec3{rho * std::cos(t), rho * std::sin(t), 0.5 * std::sin(8 * t)}), 1e-14);
  }
  const testing::ProcessResult bad =
      testing::run_process(HULA_CLI_PATH, {"helical-offset", in, "--distance", "0.5", "--frame", "darboux", "-o", out});
  EXPECT_EQ(bad.exit_code, 3);
  EXPECT_EQ(testing::stderr_error(bad)["where"]["field"], "frame");
}

}  // namespace
}  // namespace hula
