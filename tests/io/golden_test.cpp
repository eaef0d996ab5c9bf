// SPDX-License-Identifier: MIT
// Golden tests (tests/data/io/README.md gives provenance and tolerances):
// the rational unit circle evaluated through the library and through
// `hula eval` against the closed form; the thesis's cumulative chord lengths
// through the CSV reader and through `hula demo`; the format samples.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "hula/io/atomic_file.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/points_file.hpp"
#include "hula/nurbs/arc_length.hpp"
#include "hula/testing/run_process.hpp"

namespace hula::io {
namespace {

using nlohmann::json;

std::string data(const std::string& name) {
  const char* root = std::getenv("HULA_TEST_DATA");
  return (std::filesystem::path(root ? root : "tests/data") / "io" / name).string();
}

json load(const std::string& name) { return json::parse(read_text_file(data(name))); }

// checks: circle_rational.json evaluated by the library matches the closed form of the unit circle.
TEST(IoGolden, RationalCircleMatchesClosedForm) {
  const curve::Curve f = read_curve_file(data("circle_rational.json"));
  const json expected = load("circle_eval_expected.json");
  const double tol = expected["tolerance"], dtol = expected["derivative_tolerance"];
  EXPECT_EQ(f.nurbs().dimension(), 2);
  for (const auto& c : expected["cases"]) {
    const double t = c["t"];
    const auto d = f.nurbs().derivatives(t, 1);
    EXPECT_NEAR(d[0].x, c["position"][0].get<double>(), tol) << "t = " << t;
    EXPECT_NEAR(d[0].y, c["position"][1].get<double>(), tol) << "t = " << t;
    if (c.contains("first_derivative")) {
      const double dx = c["first_derivative"][0], dy = c["first_derivative"][1];
      EXPECT_NEAR(d[1].x, dx, dtol * std::hypot(dx, dy)) << "t = " << t;
      EXPECT_NEAR(d[1].y, dy, dtol * std::hypot(dx, dy)) << "t = " << t;
    }
  }
  const double L = expected["length"];
  EXPECT_NEAR(nurbs::arc_length(f.nurbs()), L, expected["length_tolerance"].get<double>() * L);
}

// checks: `hula eval` on circle_rational.json prints the closed-form circle points as [x, y].
TEST(IoGolden, CliEvalOfRationalCircle) {
  const json expected = load("circle_eval_expected.json");
  std::string at;
  for (const auto& c : expected["cases"]) at += (at.empty() ? "" : ",") + c["t"].dump();
  const auto r =
      testing::run_process(HULA_CLI_PATH, {"eval", data("circle_rational.json"), "--at", at, "--derivatives", "1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json out = json::parse(r.out);
  const double tol = expected["tolerance"];
  ASSERT_EQ(out["results"].size(), expected["cases"].size());
  for (std::size_t i = 0; i < expected["cases"].size(); ++i) {
    const json& c = expected["cases"][i];
    const json& got = out["results"][i];
    EXPECT_EQ(got["t"], c["t"]);
    ASSERT_EQ(got["derivatives"][0].size(), 2u);
    for (std::size_t k = 0; k < 2; ++k)
      EXPECT_NEAR(got["derivatives"][0][k].get<double>(), c["position"][k].get<double>(), tol) << "t = " << c["t"];
  }
}

// checks: the thesis's cumulative chord lengths 47.17, 111.20, 158.37 from thesis_points.csv and from `hula demo`.
TEST(IoGolden, ThesisChordLengths) {
  const json expected = load("thesis_chord_lengths.json");
  const double tol = expected["tolerance"];
  const PointSet pts = read_points_file(data(expected["points"]));
  const std::vector<double> L = nurbs::cumulative_chord_lengths(pts.points);
  ASSERT_EQ(L.size(), expected["cumulative_chord_lengths"].size());
  for (std::size_t i = 0; i < L.size(); ++i)
    EXPECT_NEAR(L[i], expected["cumulative_chord_lengths"][i].get<double>(), tol) << i;

  const auto r = testing::run_process(HULA_CLI_PATH, {"demo"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json demo = json::parse(r.out);
  const json& chords = demo["examples"][0]["cumulative_chord_lengths"];
  ASSERT_EQ(chords.size(), L.size());
  for (std::size_t i = 0; i < L.size(); ++i)
    EXPECT_NEAR(chords[i].get<double>(), expected["cumulative_chord_lengths"][i].get<double>(), tol) << i;
}

// checks: the format samples load with their documented values (bezier midpoint (1,1) by de Casteljau;
// the interpolated sample passes through its end points with the clamped end derivative).
TEST(IoGolden, FormatSamples) {
  const curve::Curve b = read_curve_file(data("bezier_2d.json"));
  EXPECT_EQ(b.kind(), curve::Kind::Bezier);
  EXPECT_NEAR(b.nurbs().evaluate(0.5).x, 1.0, 1e-15);
  EXPECT_NEAR(b.nurbs().evaluate(0.5).y, 1.0, 1e-15);
  // The parabola (2t, 4t(1 - t)) has length ∫₀² √(1 + u²) du = √5 + asinh(2) / 2.
  const double parabola = std::sqrt(5.0) + std::asinh(2.0) / 2.0;
  EXPECT_NEAR(nurbs::arc_length(b.nurbs()), parabola, 1e-12 * parabola);

  const curve::Curve s = read_curve_file(data("interpolated_thesis.json"));
  EXPECT_EQ(s.kind(), curve::Kind::Interpolated);
  EXPECT_NEAR(distance(s.nurbs().evaluate(0.0), Vec3{0, 0, 0}), 0.0, 1e-12);
  EXPECT_NEAR(distance(s.nurbs().evaluate(1.0), Vec3{120, 0, 0}), 0.0, 1e-12);
  EXPECT_NEAR(distance(s.nurbs().derivatives(1.0, 1)[1], Vec3{100, 0, 0}), 0.0, 1e-9 * 100);
}

}  // namespace
}  // namespace hula::io
