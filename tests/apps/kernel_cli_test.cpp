// SPDX-License-Identifier: MIT
// Property tests (seeded random curves) of the kernel commands of `hula`
// (issue 10, item 6), run as a process and checked against the library:
// edit insert-knot / refine / elevate / reparam leave the curve unchanged to
// 1e-12 and equal the library's result; split gives halves that join with
// C^(p−m) at the split; approximate meets its tolerance with the fewest
// control points its search finds; deviation of a curve with itself is 0;
// closest, continuity and energy against closed forms (circle) and the library.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/diffgeom/continuity.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/nurbs/approximate.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/nurbs/elevate.hpp"
#include "hula/nurbs/knot_removal.hpp"
#include "hula/nurbs/refine.hpp"
#include "hula/nurbs/reparam.hpp"
#include "hula/studies/tolerance_fit.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/process_json.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif

namespace hula {
namespace {

using nlohmann::json;
using nurbs::NurbsCurve;
using testing::ProcessResult;

constexpr int kCases = 6;  // random curves per property (each case runs the binary)

json run_ok(const std::vector<std::string>& args) {
  return testing::stdout_json(testing::run_process(HULA_CLI_PATH, args));
}

struct Case {
  testing::TempDir dir;
  NurbsCurve curve;
  std::string in;
  std::string out;
  explicit Case(std::uint64_t seed, testing::RandomCurveSpec spec = {})
      : curve([&] {
          Rng rng(seed);
          spec.rational = seed % 2 == 1;
          spec.degree = 1 + static_cast<int>(seed % 5);
          return testing::random_curve(rng, spec);
        }()),
        in((dir / "in.json").string()),
        out((dir / "out.json").string()) {
    io::write_curve_file(in, curve);
  }
  [[nodiscard]] NurbsCurve result() const { return io::read_curve_file(out).nurbs(); }
};

// checks: `edit remove-knots` undoes `edit refine` (the knot vector of the input again, control points to
// 1e-10 × size) and reports what nurbs::remove_knots reports; with --at it removes that knot only.
TEST(KernelCli, RemoveKnotsUndoesRefine) {
  for (std::uint64_t seed = 1; seed <= kCases; ++seed) {
    Case c(seed);
    const nurbs::Interval d = c.curve.domain();
    std::vector<double> x;
    for (const double f : {0.21, 0.43, 0.77})
      if (c.curve.knots().multiplicity(d.start + f * d.length()) == 0) x.push_back(d.start + f * d.length());
    const NurbsCurve refined = nurbs::refine_knots(c.curve, x);
    io::write_curve_file(c.in, refined);
    const std::string tol = hula::format_number(1e-9 * c.curve.model_size());
    const json all = run_ok({"edit", "remove-knots", c.in, "--tolerance", tol, "-o", c.out});
    const nurbs::KnotRemovalResult lib = nurbs::remove_knots(refined, 1e-9 * c.curve.model_size());
    EXPECT_EQ(all["operation"], "remove-knots");
    EXPECT_EQ(all["removed"].get<std::size_t>(), x.size()) << seed;
    EXPECT_EQ(all["removed"].get<std::size_t>(), lib.removed) << seed;
    const NurbsCurve back = c.result();
    ASSERT_EQ(back.knots(), c.curve.knots()) << seed;
    for (std::size_t i = 0; i < back.control_points().size(); ++i)
      EXPECT_LE(distance(back.control_points()[i], c.curve.control_points()[i]), 1e-10 * c.curve.model_size());
    if (x.empty()) continue;
    const json one =
        run_ok({"edit", "remove-knots", c.in, "--tolerance", tol, "--at", hula::format_number(x[0]), "-o", c.out});
    EXPECT_EQ(one["removed"].get<std::size_t>(), 1u) << seed;
    EXPECT_EQ(c.result().control_points().size(), refined.control_points().size() - 1) << seed;
  }
}

// checks: `edit insert-knot` equals nurbs::insert_knot and leaves the curve unchanged (≤ 1e-12 × size).
TEST(KernelCli, InsertKnotLeavesCurveUnchanged) {
  for (std::uint64_t seed = 1; seed <= kCases; ++seed) {
    Case c(seed);
    const nurbs::Interval d = c.curve.domain();
    const double u = d.start + 0.37 * d.length();
    const int times = std::max(1, c.curve.degree() - c.curve.knots().multiplicity(u));
    run_ok({"edit", "insert-knot", c.in, "--at", std::to_string(u), "--times", std::to_string(times), "-o", c.out});
    const NurbsCurve got = c.result();
    const double used = std::stod(std::to_string(u));
    EXPECT_EQ(got, nurbs::insert_knot(c.curve, used, times)) << seed;
    EXPECT_LE(testing::max_deviation(c.curve, got), 1e-12 * c.curve.model_size()) << seed;
  }
}

// checks: `edit refine` and `edit elevate` equal the library and leave the curve unchanged.
TEST(KernelCli, RefineAndElevateLeaveCurveUnchanged) {
  for (std::uint64_t seed = 1; seed <= kCases; ++seed) {
    Case c(seed);
    const nurbs::Interval d = c.curve.domain();
    const std::vector<double> x = {d.start + 0.125 * d.length(), d.start + 0.5 * d.length(),
                                   d.start + 0.875 * d.length()};
    std::string list;
    for (double v : x) list += (list.empty() ? "" : ",") + io::Json(v).dump();
    run_ok({"edit", "refine", c.in, "--knots", list, "-o", c.out});
    EXPECT_EQ(c.result(), nurbs::refine_knots(c.curve, x)) << seed;
    EXPECT_LE(testing::max_deviation(c.curve, c.result()), 1e-12 * c.curve.model_size()) << seed;
    run_ok({"edit", "elevate", c.in, "--times", "2", "-o", c.out});
    EXPECT_EQ(c.result().degree(), c.curve.degree() + 2);
    EXPECT_LE(testing::max_deviation(c.curve, c.result()), 1e-12 * c.curve.model_size()) << seed;
  }
}

// checks: `edit reparam --domain -2,5` maps the domain affinely: R(−2 + 7 s) = C(a + L s) to 1e-12,
// and `edit reverse` traverses it backwards: R(t) = C(a + b − t).
TEST(KernelCli, ReparamAndReverseKeepThePointSet) {
  for (std::uint64_t seed = 1; seed <= kCases; ++seed) {
    Case c(seed);
    run_ok({"edit", "reparam", c.in, "--domain", "-2,5", "-o", c.out});
    const NurbsCurve r = c.result();
    EXPECT_EQ(r.domain().start, -2.0);
    EXPECT_EQ(r.domain().end, 5.0);
    const nurbs::Interval d = c.curve.domain();
    for (int i = 0; i <= 100; ++i) {
      const double s = i / 100.0;
      EXPECT_LE(distance(r.evaluate(-2 + 7 * s), c.curve.evaluate(d.start + d.length() * s)),
                1e-12 * c.curve.model_size());
    }
    run_ok({"edit", "reverse", c.in, "-o", c.out});
    const NurbsCurve b = c.result();
    for (int i = 0; i <= 100; ++i) {
      const double t = d.start + d.length() * i / 100.0;
      const double mirrored = std::clamp(d.start + d.end - t, d.start, d.end);  // a + b − t may round outside
      EXPECT_LE(distance(b.evaluate(t), c.curve.evaluate(mirrored)), 1e-12 * c.curve.model_size());
    }
  }
}

// checks: `edit split --at t` gives halves equal to the curve on [a, t] and [t, b] whose join is
// C^(p−m) (m = multiplicity of t in the curve), judged by diffgeom::join_continuity.
TEST(KernelCli, SplitHalvesJoinWithTheCurvesContinuity) {
  for (std::uint64_t seed = 1; seed <= kCases; ++seed) {
    Case c(seed);
    const nurbs::Interval d = c.curve.domain();
    const double t = d.start + 0.41 * d.length();
    const std::string second = (c.dir / "second.json").string();
    const json j = run_ok({"edit", "split", c.in, "--at", io::Json(t).dump(), "-o", c.out, "--second", second});
    ASSERT_EQ(j["curves"].size(), 2U);
    const NurbsCurve a = c.result();
    const NurbsCurve b = io::read_curve_file(second).nurbs();
    EXPECT_EQ(a.domain().end, t);
    EXPECT_EQ(b.domain().start, t);
    EXPECT_LE(testing::max_deviation(a, c.curve), 1e-12 * c.curve.model_size()) << seed;
    EXPECT_LE(testing::max_deviation(b, c.curve), 1e-12 * c.curve.model_size()) << seed;
    const int expected = std::min(3, c.curve.degree() - c.curve.knots().multiplicity(t));
    EXPECT_GE(diffgeom::join_continuity(a, b).parametric, expected) << seed;
    const json cont = run_ok({"continuity", c.out, second});
    EXPECT_EQ(cont["parametric"], "C" + std::to_string(diffgeom::join_continuity(a, b).parametric)) << seed;
  }
}

// checks: `approximate --tolerance` writes the curve of studies::fit_within_tolerance (degree 3, ends
// on the first and last point, chord-length start): every point within the tolerance of the written
// curve (closest point, re-measured here), the ends exact, and no more control points than the plain
// least-squares search nurbs::approximate_to_tolerance needs.
TEST(KernelCli, ApproximateMeetsToleranceCompactly) {
  testing::TempDir dir;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    Rng rng(seed);
    std::vector<Vec3> pts;
    json arr = json::array();
    for (int i = 0; i < 80; ++i) {
      const double u = i / 79.0;
      pts.push_back({10 * std::cos(2 * u) + rng.uniform(-0.02, 0.02), 5 * std::sin(3 * u), u * u});
      arr.push_back({pts.back().x, pts.back().y, pts.back().z});
    }
    const std::string pfile = (dir / "pts.json").string(), out = (dir / "fit.json").string();
    io::write_file_atomically(pfile, arr.dump());
    const double tol = 0.05;
    const json j = run_ok({"approximate", "--points", pfile, "--tolerance", "0.05", "-o", out});
    const NurbsCurve c = io::read_curve_file(out).nurbs();
    studies::ToleranceFitOptions o;
    o.tolerance = tol;
    o.degree = 3;
    o.min_degree = 3;
    o.ends = studies::FitEnds::Interpolated;
    o.max_control_points = pts.size();
    const studies::ToleranceFit lib =
        studies::fit_within_tolerance(pts, nurbs::parameterise(pts, nurbs::Parameterisation::ChordLength), {}, o);
    EXPECT_EQ(c, lib.faired) << seed;
    for (const Vec3& q : pts) EXPECT_LE(nurbs::closest_point(c, q).distance, tol * (1 + 1e-9));
    EXPECT_EQ(c.evaluate(0.0), pts.front());
    EXPECT_EQ(c.evaluate(1.0), pts.back());
    EXPECT_LE(c.control_points().size(), nurbs::approximate_to_tolerance(pts, tol).fit.curve.control_points().size())
        << seed;
    EXPECT_EQ(j["control_points"], c.control_points().size());
    EXPECT_LE(j["max_deviation"].get<double>(), tol);
  }
}

// checks: `deviation A A` is 0 in every statistic; `closest` equals nurbs::closest_point.
TEST(KernelCli, DeviationWithItselfIsZeroAndClosestMatchesLibrary) {
  for (std::uint64_t seed = 1; seed <= kCases; ++seed) {
    Case c(seed);
    const json j = run_ok({"deviation", c.in, c.in, "--samples", "513"});
    EXPECT_EQ(j["max"], 0.0);
    EXPECT_EQ(j["mean"], 0.0);
    EXPECT_EQ(j["mean_axis"], json::array({0.0, 0.0, 0.0}));
    const json k = run_ok({"closest", c.in, "--point", "1,2,3"});
    const nurbs::ClosestPointResult r = nurbs::closest_point(c.curve, {1, 2, 3});
    EXPECT_EQ(k["results"][0]["t"].get<double>(), r.t) << seed;
    EXPECT_EQ(k["results"][0]["distance"].get<double>(), r.distance) << seed;
  }
}

// checks: `energy` of the rational circle of radius R = 2: ∫κ² ds = (1/R²)·2πR = π and
// ∫(dκ/ds)² ds = 0, the closed forms.
TEST(KernelCli, EnergyOfCircleIsClosedForm) {
  testing::TempDir dir;
  const std::string in = (dir / "circle.json").string();
  io::write_curve_file(in, testing::rational_circle(2.0));
  const json j = run_ok({"energy", in});
  EXPECT_NEAR(j["bending"]["value"].get<double>(), std::numbers::pi, 1e-9);
  EXPECT_NEAR(j["curvature_variation"]["value"].get<double>(), 0.0, 1e-9);
}

// checks (issue 26): `edit to-nurbs` converts a natural (exact) curve file to a NURBS within --tolerance — measured
// here against the closed-form circle κ = 2 (radius 1/2) at 500 arc lengths — and a law curve likewise; the other
// edits refuse a natural curve by name instead of editing its stand-in.
TEST(KernelCli, ToNurbsConvertsExactCurves) {
  testing::TempDir dir;
  const std::string in = (dir / "circle.json").string(), out = (dir / "circle-nurbs.json").string();
  io::write_file_atomically(in, R"json({"kind": "natural", "curvature": "2", "length": 3, "tolerance": 1e-12})json");
  const json j = run_ok({"edit", "to-nurbs", in, "--tolerance", "1e-9", "-o", out});
  EXPECT_EQ(j["operation"], "to-nurbs");
  EXPECT_EQ(j["from"], "natural");
  EXPECT_LE(j["max_deviation"].get<double>(), 1e-9);
  const NurbsCurve c = io::read_curve_file(out).nurbs();
  EXPECT_EQ(c.domain().end, 3.0);
  for (int i = 0; i <= 500; ++i) {
    const double s = 3.0 * i / 500.0;
    EXPECT_LT(distance(c.derivatives(s, 0)[0], Vec3{0.5 * std::sin(2 * s), 0.5 - 0.5 * std::cos(2 * s), 0.0}),
              1e-9 + 1e-12)
        << "s = " << s;
  }
  const std::string law = (dir / "law.json").string();
  io::write_file_atomically(law, R"json({"kind": "law", "expression": "vec(cos(t), sin(t))", "domain": [0, 3]})json");
  const json l = run_ok({"edit", "to-nurbs", law, "--tolerance", "1e-8", "-o", out});
  EXPECT_EQ(l["from"], "law");
  EXPECT_LE(l["max_deviation"].get<double>(), 1e-8);
  const ProcessResult r = testing::run_process(HULA_CLI_PATH, {"edit", "reverse", in, "-o", out});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(testing::stderr_error(r)["message"].get<std::string>().find("is a natural curve"), std::string::npos);
  // Below the curve's integration tolerance the conversion is refused naming the tolerance.
  const ProcessResult low =
      testing::run_process(HULA_CLI_PATH, {"edit", "to-nurbs", in, "--tolerance", "1e-13", "-o", out});
  EXPECT_EQ(low.exit_code, 3);
  EXPECT_EQ(testing::stderr_error(low)["where"]["field"], "tolerance");
}

// checks `edit to-law` on seeded random curves (degrees 1-5, rational or not): the written law curve, evaluated
// exactly (curve::Curve of the file, its law), equals the input NURBS to 1e-12 × size at 1,000 parameters and its
// reported max_difference is below that; its file is a "law" kind on the same domain; a law file is refused naming
// "curve" (exit 3).
TEST(KernelCli, ToLawWritesTheCurveOutExactly) {
  for (std::uint64_t seed = 0; seed < kCases; ++seed) {
    const Case c(seed);
    const json j = run_ok({"edit", "to-law", c.in, "-o", c.out});
    EXPECT_EQ(j["operation"], "to-law");
    EXPECT_EQ(j["degree"], c.curve.degree());
    EXPECT_EQ(j["curve"]["kind"], "law");
    const curve::Curve law = io::read_curve_file(c.out);
    ASSERT_EQ(law.kind_name(), "law");
    ASSERT_TRUE(law.has_exact_evaluation());
    double size = 1.0;
    for (const Vec3& p : c.curve.control_points()) size = std::max(size, norm(p));
    const Interval d = c.curve.domain();
    EXPECT_EQ(law.domain().start, d.start);
    EXPECT_EQ(law.domain().end, d.end);
    double worst = 0.0;
    for (int i = 0; i <= 1000; ++i) {
      const double t = i == 1000 ? d.end : d.start + (d.end - d.start) * i / 1000.0;
      worst = std::max(worst, distance(law.derivatives(t, 0)[0], c.curve.evaluate(t)));
    }
    EXPECT_LE(worst, 1e-12 * size) << "seed " << seed;
    EXPECT_LE(j["max_difference"].get<double>(), 1e-12 * size);
  }
  const Case c(1);
  (void)run_ok({"edit", "to-law", c.in, "-o", c.out});
  const ProcessResult again = testing::run_process(HULA_CLI_PATH, {"edit", "to-law", c.out, "-o", c.in});
  EXPECT_EQ(again.exit_code, 3);
  EXPECT_EQ(testing::stderr_error(again)["where"]["field"], "curve");
}

// checks `edit rebuild`: a cubic Bézier rebuilt with 9 control points is reproduced (1e-12 of its size at 1,001
// parameters, max_deviation at that level) and the file equals nurbs::rebuild's curve; a circle rebuilt with 16
// cubic control points reports the deviation the closed form gives (||C(s_i)| − R| at the same 1,001 samples, to
// 1e-9); too few control points exit 3 naming control_points, a law curve exit 3 naming curve.
TEST(KernelCli, RebuildReportsItsDeviation) {
  const testing::TempDir dir;
  const std::string in = (dir / "in.json").string();
  const std::string out = (dir / "out.json").string();
  const NurbsCurve bezier(3, {0, 0, 0, 0, 1, 1, 1, 1}, std::vector<Vec3>{{0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, 0}});
  io::write_curve_file(in, bezier);
  const json j = run_ok({"edit", "rebuild", in, "--control-points", "9", "-o", out});
  EXPECT_EQ(j["operation"], "rebuild");
  EXPECT_EQ(j["degree"], 3);
  EXPECT_EQ(j["control_points"], 9);
  EXPECT_EQ(j["samples"], 201);
  EXPECT_EQ(j["curve"]["control_points"], 9);
  EXPECT_LE(j["max_deviation"].get<double>(), 1e-12 * bezier.model_size());
  const NurbsCurve got = io::read_curve_file(out).nurbs();
  EXPECT_EQ(got, nurbs::rebuild(bezier, {.control_points = 9}).curve);
  EXPECT_LE(testing::max_deviation(bezier, got), 1e-12 * bezier.model_size());

  const double R = 3.0;
  io::write_curve_file(in, testing::rational_circle(R));
  const json k = run_ok({"edit", "rebuild", in, "--degree", "3", "--control-points", "16", "-o", out});
  const NurbsCurve ring = io::read_curve_file(out).nurbs();
  double worst = 0.0;
  for (int i = 0; i <= 1000; ++i) worst = std::max(worst, std::abs(norm(ring.evaluate(i / 1000.0)) - R));
  EXPECT_NEAR(k["max_deviation"].get<double>(), worst, 1e-9 * R);
  EXPECT_GT(worst, 1e-6 * R);

  const ProcessResult few =
      testing::run_process(HULA_CLI_PATH, {"edit", "rebuild", in, "--degree", "3", "--control-points", "3", "-o", out});
  EXPECT_EQ(few.exit_code, 3);
  EXPECT_EQ(testing::stderr_error(few)["where"]["field"], "control_points");
  (void)run_ok({"edit", "to-law", in, "-o", out});
  const ProcessResult law =
      testing::run_process(HULA_CLI_PATH, {"edit", "rebuild", out, "--control-points", "8", "-o", in});
  EXPECT_EQ(law.exit_code, 3);
  EXPECT_EQ(testing::stderr_error(law)["where"]["field"], "curve");
}

// checks `edit reduce-degree` on a rational curve: the circle elevated once comes back to its degree with a bound
// at rounding level and |C(t)| = R at 1,001 parameters (closed form); a cubic whose reduced weight is negative
// exits 4 naming the curve.
TEST(KernelCli, ReduceDegreeTakesRationalCurves) {
  const testing::TempDir dir;
  const std::string in = (dir / "in.json").string();
  const std::string out = (dir / "out.json").string();
  const double R = 2.5;
  io::write_curve_file(in, nurbs::elevate_degree(testing::rational_circle(R), 1));
  const json j = run_ok({"edit", "reduce-degree", in, "--tolerance", "0", "-o", out});
  EXPECT_EQ(j["curve"]["degree"], 2);
  EXPECT_LE(j["error_bound"].get<double>(), 1e-12 * 2 * R);
  const NurbsCurve back = io::read_curve_file(out).nurbs();
  EXPECT_TRUE(back.is_rational());
  for (int i = 0; i <= 1000; ++i) EXPECT_NEAR(norm(back.evaluate(i / 1000.0)), R, 1e-12 * R) << i;
  io::write_curve_file(in, NurbsCurve(3, {0, 0, 0, 0, 1, 1, 1, 1},
                                      std::vector<Vec3>{{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}}, {1, 0.1, 1, 1}));
  const ProcessResult bad =
      testing::run_process(HULA_CLI_PATH, {"edit", "reduce-degree", in, "--tolerance", "100", "-o", out});
  EXPECT_EQ(bad.exit_code, 4);
  EXPECT_EQ(testing::stderr_error(bad)["where"]["field"], "curve");
}

}  // namespace
}  // namespace hula
