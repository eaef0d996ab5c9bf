// SPDX-License-Identifier: MIT
// The io entries the commands answer through (curve_queries, curve_edits,
// exact_curves, optimise_request, campaign_file), checked against closed
// forms: a circle of radius R has length 2πR, bending energy ∫κ² ds = 2π/R,
// no curvature variation, C∞ joins with itself; a curve split in two joins
// C3 and G3 at the split; an edit that keeps the shape (knot insertion,
// elevation) deviates by 0; the solver-settings reader keeps the evaluation
// budget and refuses settings an algorithm does not take; a campaign sweep
// expands settings × seeds in file order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/rng.hpp"
#include "hula/io/campaign_file.hpp"
#include "hula/io/curve_edits.hpp"
#include "hula/io/curve_queries.hpp"
#include "hula/io/exact_curves.hpp"
#include "hula/io/json_text.hpp"
#include "hula/io/json_write.hpp"
#include "hula/io/optimise_request.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::io {
namespace {

// Closed forms of a circle of radius 3: length 6π, ∫κ² ds = 2π/3, ∫(dκ/ds)² ds = 0, planar, weights √½.
TEST(CurveQueries, CircleHasItsClosedForms) {
  const nurbs::NurbsCurve c = testing::rational_circle(3.0);
  const Json d = curve_description_json(c);
  EXPECT_NEAR(d["length"].get<double>(), 6 * std::numbers::pi, 1e-9);
  EXPECT_TRUE(d["rational"].get<bool>());
  EXPECT_TRUE(d["planarity"]["planar"].get<bool>());
  EXPECT_NEAR(d["weights"][1].get<double>(), std::sqrt(0.5), 1e-15);
  const Json m = curve_description_with_maximum_curvature_json(c);
  EXPECT_NEAR(m["maximum_curvature"]["value"].get<double>(), 1.0 / 3.0, 1e-9);
  const Json e = energy_answer(curve::Curve(c));
  EXPECT_NEAR(e["bending"]["value"].get<double>(), 2 * std::numbers::pi / 3.0, 1e-8);
  EXPECT_NEAR(e["curvature_variation"]["value"].get<double>(), 0.0, 1e-12);
}

// The streamed description (`hula info`'s) is format_json of curve_description_json byte for byte, on the
// 2-D rational circle, a 2-D polyline with a zero end derivative, and random curves of degrees 1-7,
// rational or not, clamped or not.
TEST(CurveQueries, StreamedDescriptionIsTheTreesText) {
  const auto streamed = [](const nurbs::NurbsCurve& c) {
    std::string text;
    JsonText w(text, true);
    w.begin_object();
    DescriptionWriter(c).write_members(w);
    w.end_object();
    return text + "\n";
  };
  std::vector<nurbs::NurbsCurve> curves{
      testing::rational_circle(3.0), nurbs::NurbsCurve(1, {0, 0, 0.5, 1, 1}, {{0, 0, 0}, {1, 2, 0}, {1, 2, 0}}, {}, 2)};
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    Rng rng(seed, 27);
    testing::RandomCurveSpec spec;
    spec.degree = 1 + static_cast<int>(rng.below(7));
    spec.rational = rng.below(2) == 0;
    spec.clamped = rng.below(2) == 0;
    curves.push_back(testing::random_curve(rng, spec));
  }
  for (const nurbs::NurbsCurve& c : curves) {
    const std::string text = streamed(c);
    EXPECT_EQ(text, format_json(curve_description_json(c)));
    EXPECT_GT(text.size(), 200u);
  }
  EXPECT_NE(streamed(curves[1]).find("\"end\": null"), std::string::npos);  // the zero end derivative
}

// The nearest point of a circle to (5, 0) is (3, 0) at distance 2; to (0, −6): (0, −3) at 3.
TEST(CurveQueries, ClosestPointsOfACircle) {
  const curve::Curve c(testing::rational_circle(3.0));
  const std::vector<Vec3> points{{5, 0, 0}, {0, -6, 0}};
  const std::vector<int> dims{2, 3};
  const Json a = closest_answer(c, points, dims);
  ASSERT_EQ(a["results"].size(), 2u);
  EXPECT_NEAR(a["results"][0]["distance"].get<double>(), 2.0, 1e-9);
  EXPECT_NEAR(a["results"][1]["distance"].get<double>(), 3.0, 1e-9);
  EXPECT_NEAR(a["results"][1]["closest"][1].get<double>(), -3.0, 1e-9);
  EXPECT_EQ(a["results"][0]["point"].size(), 2u);  // as given
  EXPECT_EQ(a["results"][1]["point"].size(), 3u);
  EXPECT_FALSE(a.contains("law_stand_in_deviation"));
}

// A cubic split at t = 0.4 joins C3 and G3 with itself; deviation of a curve from its own knot
// insertion and degree elevation is 0.
TEST(CurveEdits, SplitJoinsSmoothlyAndShapeKeepingEditsDeviateByZero) {
  const nurbs::NurbsCurve c(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, 0}});
  const curve::Curve file(c);
  const CurveEditAnswer split = edit_curve(file, "c.json", {.edit = CurveEdit::Split, .at = 0.4});
  ASSERT_EQ(split.curves.size(), 2u);
  const Json join = join_continuity_answer(curve::Curve(split.curves[0]), curve::Curve(split.curves[1]));
  EXPECT_EQ(join["parametric"], "C3");
  EXPECT_EQ(join["geometric"], "G3");
  EXPECT_EQ(split.report["at"], 0.4);
  for (const CurveEditRequest& q : {CurveEditRequest{.edit = CurveEdit::InsertKnot, .at = 0.3, .times = 2},
                                    CurveEditRequest{.edit = CurveEdit::Elevate, .times = 2}}) {
    const CurveEditAnswer r = edit_curve(file, "c.json", q);
    const Json dev = deviation_answer(file, curve::Curve(r.curves.front()), {.samples = 101}, "parameter");
    EXPECT_LE(dev["max"].get<double>(), 1e-12);
  }
  const Json summary = edited_curve_summary("out.json", split.curves[0]);
  EXPECT_EQ(summary["domain"][1], 0.4);
}

// Edits that need the NURBS itself refuse an exact (natural) curve, naming the file.
TEST(CurveEdits, RefusesAnExactCurveNamingTheFile) {
  const curve::Curve exact =
      clothoid_curve(clothoid_answer({.end_point = {3, 1, 0}, .end_angle = 0.5}).segments, curve::kNaturalTolerance);
  try {
    (void)edit_curve(exact, "exact.json", {.edit = CurveEdit::Reverse});
    FAIL() << "an exact curve was edited";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Errc::InvalidArgument);
    EXPECT_NE(e.message().find("exact.json"), std::string::npos) << e.message();
  }
}

// A clothoid G1 fit between (0,0) at angle 0 and (3,1) at angle 0.5 reaches the end and its curvature is
// linear in s (κ(L/2) is the mean of the end curvatures).
TEST(ExactCurves, ClothoidCurvatureIsLinearInArcLength) {
  ClothoidRequest q{.end_point = {3, 1, 0}, .end_angle = 0.5};
  const double L = clothoid_answer(q).json["length"].get<double>();
  q.at = {0.0, 0.5 * L, L};
  const Json a = clothoid_answer(q).json;
  const Json& p = a["points"];
  EXPECT_NEAR(p[2]["point"][0].get<double>(), 3.0, 1e-9);
  EXPECT_NEAR(p[2]["point"][1].get<double>(), 1.0, 1e-9);
  EXPECT_NEAR(p[2]["theta"].get<double>(), 0.5, 1e-9);
  EXPECT_NEAR(p[1]["kappa"].get<double>(), 0.5 * (p[0]["kappa"].get<double>() + p[2]["kappa"].get<double>()), 1e-12);
}

// The budget of evaluations bounds the generations (evaluations / population); Nelder–Mead refuses a
// population and pagmo a budget of evaluations, naming the setting; only ga-binary takes a boost; pagmo
// takes the time limit and the cancellation token.
TEST(SolverOptions, KeepsTheBudgetAndRefusesWhatAnAlgorithmDoesNotTake) {
  const optim::SolverOptions o =
      solver_options({.algorithm = "ga-real", .population = 20, .evaluations = 500, .seed = 4});
  const auto& ga = std::get<optim::RealGaOptions>(o);
  EXPECT_EQ(ga.population, 20u);
  EXPECT_EQ(ga.run.stop.generations, 25u);
  EXPECT_EQ(ga.run.stop.max_evaluations, 500u);
  EXPECT_EQ(ga.run.seed, 4u);
  const auto refused = [](const SolverRequest& q, const std::string& field) {
    try {
      (void)solver_options(q);
      ADD_FAILURE() << q.algorithm << " took " << field;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), Errc::InvalidOption);
      EXPECT_EQ(e.where().field, field);
      EXPECT_NE(e.message().find(q.algorithm), std::string::npos) << e.message();
    }
  };
  refused({.algorithm = "nelder-mead", .population = 10}, "population");
  refused({.algorithm = "pagmo-de", .evaluations = 100}, "evaluations");
  refused({.algorithm = "nsga2", .boost = std::pair{1.0, 4.0}}, "boost");
  const optim::SolverOptions b = solver_options({.algorithm = "ga-binary", .boost = std::pair{1.0, 4.0}});
  EXPECT_EQ(std::get<optim::BinaryGaOptions>(b).boost_end, 4.0);
  const optim::CancellationToken token;
  const optim::SolverOptions p = solver_options({.algorithm = "pagmo-de", .time = 1.5, .cancel = &token});
  EXPECT_EQ(std::get<optim::PagmoOptions>(p).wall_time_seconds, 1.5);
  EXPECT_EQ(std::get<optim::PagmoOptions>(p).cancel, &token);
}

// The sphere's front: one objective gives {"best"} with the smallest objective; the built-in problems'
// hypervolume reference is 1.1 per objective.
TEST(SolverOptions, BuiltinProblemReferenceAndBestSolution) {
  const auto [problem, reference] = builtin_problem("zdt1", 4, 0);
  EXPECT_EQ(reference, (std::vector<double>{1.1, 1.1}));
  optim::SolveResult r;
  r.solutions = {{.variables = {0, 0, 0, 0}, .objectives = {0.0, 1.0}},
                 {.variables = {1, 0, 0, 0}, .objectives = {1.0, 0.0}}};
  const Json front = solve_result_to_json(r, problem, reference);
  // The front {(0, 1), (1, 0)} dominates two boxes up to (1.1, 1.1): 0.11 + 0.11 minus their 0.01 overlap.
  EXPECT_NEAR(front["hypervolume"].get<double>(), 1.1 * 0.1 + 0.1 * 1.1 - 0.1 * 0.1, 1e-12);
  EXPECT_EQ(front["front"][0]["objectives"][0], 0.0);
}

// A sweep of 2 settings × 2 seeds after one listed item, ids as documented; the item's study file gets
// its seed and settings merged in.
TEST(CampaignFile, SweepExpandsSettingsTimesSeedsInFileOrder) {
  const auto dir = std::filesystem::temp_directory_path() / "hula-campaign-test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "s.json") << R"({"study": "fair-knots", "seed": 1, "ga": {"population": 8}})";
  std::ofstream(dir / "c.json") << R"({"format": "hula-campaign", "version": 1,
    "items": [{"study": "s.json", "id": "first"}],
    "sweep": {"study": "s.json", "seeds": [3, 4], "settings": [{"ga": {"population": 10}}, {"method": "ga"}]}})";
  const std::vector<CampaignItem> items = read_campaign_file(dir / "c.json");
  std::vector<std::string> ids;
  for (const CampaignItem& i : items) ids.push_back(i.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"first", "s/settings0/seed3", "s/settings0/seed4", "s/settings1/seed3",
                                           "s/settings1/seed4"}));
  const Json study = campaign_item_study(items[2]);
  EXPECT_EQ(study["seed"], 4);
  EXPECT_EQ(study["ga"]["population"], 10);
  const Json ok = campaign_item_record(items[0], 0, 0.5, 0, R"({"x": 1})", "");
  EXPECT_EQ(ok["status"], "ok");
  EXPECT_EQ(ok["result"]["x"], 1);
  const Json killed = campaign_item_record(items[1], 0, 0.5, 128 + 9, "", "");
  EXPECT_EQ(killed["error"], "terminated by signal 9");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hula::io
