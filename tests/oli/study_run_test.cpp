// SPDX-License-Identifier: MIT
// Study runs stored in the document: the study entity keeps setup, seed, run
// log and result; the result curve is a new entity with provenance; a rerun
// from what the document stored (also after reopening the file) gives the
// same curve bit for bit (the first run's stored curve is the reference).
#include "hula/oli/study_run.hpp"

#include <gtest/gtest.h>

#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

#include "hula/io/json_curve.hpp"
#include "hula/io/match_study_file.hpp"
#include "hula/io/study_file.hpp"
#include "hula/studies/curvature_match.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif
#ifndef HULA_EXAMPLES_DIR
#error "HULA_EXAMPLES_DIR must name examples/studies"
#endif

namespace hula::oli {
namespace {

// Thesis 8.2.1 Example 1 (examples/studies/match-curvature-example1.json) with its points taken from
// a point-set entity and a small GA, so the test is fast.
Json study_on(Label points) {
  Json s = Json::parse(R"({"format": "hula-study", "version": 1, "study": "match-curvature", "seed": 5,
    "lower": [[0, 0], [30, 30], [0, 0]], "upper": [[0, 0], [35, 30], [0, 0]],
    "samples": 50, "method": "ga",
    "ga": {"algorithm": "binary", "population": 12, "generations": 6, "boost_start": 3, "boost_end": 5,
           "crossover_probability": 1.0, "mutation_probability": 0.01, "precision": 0.001}})");
  s["points"] = Json::object({{"entity", points.value}});
  s["target"] = Json::object({{"of_points", Json::object({{"entity", points.value}})}, {"mirror", true}});
  return s;
}

Label add_points(Document& doc) {
  Label p;
  doc.transact("points",
               [&](Edit& e) {
                 p = e.add_point_set({{{0, 0, 0}, {5, 20, 0}, {40, 0, 0}}, 2});
               })
      .throw_if_failed();
  return p;
}

// Checks one run adds the study and its result curve with provenance, and a rerun repeats it bit-exactly.
TEST(StudyRun, RunIsStoredWithProvenanceAndRepeatsBitExactly) {
  hula::testing::TempDir dir;
  const auto path = dir / "s.hula";
  StudyRunResult first;
  {
    Document doc = Document::create(path);
    const Label p = add_points(doc);
    doc.transact("run", [&](Edit& e) { first = run_study(e, study_on(p), dir.path()); }).throw_if_failed();
    ASSERT_EQ(first.curves.size(), 1u);
    const Entity study = doc.get(first.study);
    ASSERT_EQ(study.study().runs.size(), 1u);
    EXPECT_EQ(study.study().runs[0].seed, 5u);
    ASSERT_NE(study.study().runs[0].log, nullptr);
    EXPECT_FALSE(study.study().runs[0].log->generations().empty());
    EXPECT_EQ(study.study().setup["points"]["entity"], p.value);
    const Entity curve = doc.get(first.curves[0]);
    ASSERT_TRUE(curve.provenance().has_value());
    EXPECT_EQ(curve.provenance()->operation, "study:match-curvature");
    EXPECT_EQ(curve.provenance()->inputs, (std::vector<Label>{first.study, p}));
    EXPECT_EQ(curve.provenance()->seed, 5u);
    EXPECT_EQ(io::curve_to_json(curve.curve()), first.result["curve"]);
  }
  Document doc = Document::open(path);
  StudyRunResult again;
  doc.transact("rerun", [&](Edit& e) { again = rerun_study(e, first.study, dir.path()); }).throw_if_failed();
  const std::string a = io::curve_to_json(doc.get(first.curves[0]).curve()).dump();
  const std::string b = io::curve_to_json(doc.get(again.curves[0]).curve()).dump();
  EXPECT_EQ(a, b);
  EXPECT_EQ(doc.get(first.study).study().runs.size(), 2u);
  const Study& stored = doc.get(first.study).study();
  EXPECT_EQ(stored.runs[0].result["curve"].dump(), stored.runs[1].result["curve"].dump());
  EXPECT_EQ(stored.runs[0].result["after"].dump(), stored.runs[1].result["after"].dump());
}

// Checks a failing study (unknown kind, bad reference) rolls the whole transaction back.
TEST(StudyRun, FailingStudyRollsBack) {
  Document doc;
  const Label p = add_points(doc);
  Json bad = study_on(p);
  bad["study"] = "no-such-study";
  Outcome out = doc.transact("run", [&](Edit& e) { (void)run_study(e, bad, "."); });
  EXPECT_EQ(out.error_code, "InvalidArgument");
  EXPECT_NE(out.error_message.find("no-such-study"), std::string::npos);
  Json missing = study_on(Label{99});
  out = doc.transact("run", [&](Edit& e) { (void)run_study(e, missing, "."); });
  EXPECT_EQ(out.error_code, "InvalidArgument");
  EXPECT_NE(out.error_message.find("99"), std::string::npos);
  EXPECT_EQ(doc.size(), 1u);
  EXPECT_EQ(doc.revision(), 1u);
}

// Checks the progress callback sees every generation in order (match-curvature: generations 0..6 of the
// binary GA), the same count the stored run log holds, and the run is not cancelled.
TEST(StudyRun, ProgressCallbackSeesEveryGeneration) {
  Document doc;
  const Label p = add_points(doc);
  std::vector<std::size_t> seen;
  StudyRunOptions options;
  options.on_generation = [&](const optim::GenerationLog& g) { seen.push_back(g.generation); };
  StudyRunResult r;
  doc.transact("run", [&](Edit& e) { r = run_study(e, study_on(p), ".", options); }).throw_if_failed();
  EXPECT_EQ(seen, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6}));
  ASSERT_NE(doc.get(r.study).study().runs[0].log, nullptr);
  EXPECT_EQ(doc.get(r.study).study().runs[0].log->generations().size(), seen.size());
  EXPECT_FALSE(r.cancelled);
  EXPECT_EQ(r.kind, "match-curvature");
}

// Checks cancelling from the callback after generation 2 stops the GA there and stores the best so far:
// the run log ends at generation 2, the result curve exists and its provenance says "cancelled".
TEST(StudyRun, CancelStoresBestSoFar) {
  Document doc;
  const Label p = add_points(doc);
  optim::CancellationToken cancel;
  StudyRunOptions options;
  options.cancel = &cancel;
  options.on_generation = [&](const optim::GenerationLog& g) {
    if (g.generation == 2) cancel.cancel();
  };
  StudyRunResult r;
  doc.transact("run", [&](Edit& e) { r = run_study(e, study_on(p), ".", options); }).throw_if_failed();
  EXPECT_TRUE(r.cancelled);
  const Study& stored = doc.get(r.study).study();
  ASSERT_EQ(stored.runs.size(), 1u);
  ASSERT_NE(stored.runs[0].log, nullptr);
  EXPECT_EQ(stored.runs[0].log->generations().size(), 3u);
  EXPECT_EQ(stored.runs[0].result["ga"]["termination"], "Cancelled");
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_EQ(doc.get(r.curves[0]).provenance()->details["cancelled"], true);
}

// Checks the phases let the document be read and edited from another thread while a study computes: the
// computation is paused at generation 1 (a gate in the progress callback) while this thread moves a point of
// the input point set and reads it back; the stored run equals run_study's on an unedited document bit for
// bit (curve, best points, distances: it ran on the points as read at prepare), and its curve's provenance names the
// changed input.
TEST(StudyRun, DocumentStaysEditableWhileAStudyComputes) {
  Document reference;
  StudyRunResult expected;
  const Label rp = add_points(reference);
  reference.transact("run", [&](Edit& e) { expected = run_study(e, study_on(rp), "."); }).throw_if_failed();

  Document doc;
  const Label p = add_points(doc);
  PreparedStudy prepared = prepare_study(doc, study_on(p));
  std::mutex mutex;
  std::condition_variable changed;
  bool paused = false, resume = false;
  StudyRunOptions options;
  options.on_generation = [&](const optim::GenerationLog& g) {
    if (g.generation != 1) return;
    std::unique_lock lock(mutex);
    paused = true;
    changed.notify_all();
    changed.wait(lock, [&] { return resume; });
  };
  ComputedStudy computed;
  std::thread worker([&] { computed = compute_study(std::move(prepared), ".", options); });
  {
    std::unique_lock lock(mutex);
    changed.wait(lock, [&] { return paused; });
  }
  doc.transact("drag", [&](Edit& e) { e.move_point(p, 1, {5, 25, 0}); }).throw_if_failed();
  EXPECT_EQ(doc.get(p).point_set().points[1], (Vec3{5, 25, 0}));
  {
    std::lock_guard lock(mutex);
    resume = true;
  }
  changed.notify_all();
  worker.join();
  StudyRunResult r;
  doc.transact("run", [&](Edit& e) { r = commit_study(e, std::move(computed)); }).throw_if_failed();
  EXPECT_EQ(doc.revision(), 3u);
  for (const char* member : {"curve", "best_points", "after", "start_points"})
    EXPECT_EQ(r.result[member].dump(), expected.result[member].dump()) << member;
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_EQ(io::curve_to_json(doc.get(r.curves[0]).curve()).dump(),
            io::curve_to_json(reference.get(expected.curves[0]).curve()).dump());
  const Provenance& prov = *doc.get(r.curves[0]).provenance();
  EXPECT_EQ(prov.inputs, (std::vector<Label>{r.study, p}));
  EXPECT_EQ(prov.details["inputs_changed"], Json::array({p.value}));
  EXPECT_EQ(prov.details["read_at_revision"], 1u);
  EXPECT_FALSE(reference.get(expected.curves[0]).provenance()->details.contains("inputs_changed"));
}

// Checks a rerun whose study entity is removed while it computes fails at commit (InvalidArgument naming
// the label) and leaves the document as it was.
TEST(StudyRun, RerunOfARemovedStudyFailsAtCommit) {
  Document doc;
  const Label p = add_points(doc);
  StudyRunResult first;
  doc.transact("run", [&](Edit& e) { first = run_study(e, study_on(p), "."); }).throw_if_failed();
  ComputedStudy computed = compute_study(prepare_rerun(doc, first.study), ".");
  doc.transact("remove", [&](Edit& e) { e.remove(first.study); }).throw_if_failed();
  const std::uint64_t revision = doc.revision();
  const Outcome out = doc.transact("rerun", [&](Edit& e) { (void)commit_study(e, std::move(computed)); });
  EXPECT_EQ(out.error_code, "InvalidArgument");
  EXPECT_NE(out.error_message.find(std::to_string(first.study.value)), std::string::npos);
  EXPECT_EQ(doc.revision(), revision);
}

// Checks a fair-knots study (thesis 7.3 Example 2's asymmetric points, both optimisers) stores both optima
// as curves whose energies are below the chord-length start's (0.2556 against 0.2472 from `hula fair-knots`).
TEST(StudyRun, FairKnotsStoresBothOptima) {
  Document doc;
  const Json study = Json::parse(R"({"format": "hula-study", "version": 1, "study": "fair-knots", "seed": 1,
    "points": [[0, 0], [40, 25], [80, -40], [120, 0]], "energy": "bending", "method": "both",
    "ga": {"algorithm": "real", "population": 20, "generations": 10}})");
  std::size_t generations = 0;
  StudyRunOptions options;
  options.on_generation = [&](const optim::GenerationLog&) { ++generations; };
  StudyRunResult r;
  doc.transact("run", [&](Edit& e) { r = run_study(e, study, ".", options); }).throw_if_failed();
  ASSERT_EQ(r.curves.size(), 2u);
  EXPECT_GT(generations, 10u);
  const double start = r.result["chord_length"]["energy"].get<double>();
  EXPECT_NEAR(start, 0.2555755, 1e-6);
  EXPECT_NEAR(r.result["ga"]["energy"].get<double>(), 0.2472, 1e-3);
  EXPECT_NEAR(r.result["deterministic"]["energy"].get<double>(), 0.2472, 1e-3);
  EXPECT_EQ(io::curve_to_json(doc.get(r.curves[0]).curve()), r.result["ga"]["curve"]);
  EXPECT_EQ(io::curve_to_json(doc.get(r.curves[1]).curve()), r.result["deterministic"]["curve"]);
  EXPECT_EQ(doc.get(r.curves[1]).provenance()->operation, "study:fair-knots");
}

// Checks a deterministic fair-knots study (thesis 7.3 Example 2, Nelder-Mead only) reports its simplex
// iterations as generations 0, 1, 2, ... in energy units (the last one's best is the result's energy), counted
// into the report (its evaluations are the result's less the start's energy), with the same result as a
// run that nobody watches; a progress callback that cancels the token stops it with the best so far.
TEST(StudyRun, FairKnotsDeterministicReportsGenerations) {
  const Json study = Json::parse(R"({"format": "hula-study", "version": 1, "study": "fair-knots", "seed": 1,
    "points": [[0, 0], [40, 25], [80, -40], [120, 0]], "energy": "bending", "method": "deterministic"})");
  const auto run_once = [&](const StudyRunOptions& options) {
    Document doc;
    StudyRunResult r;
    doc.transact("run", [&](Edit& e) { r = run_study(e, study, ".", options); }).throw_if_failed();
    r.result["deterministic"].erase("seconds");
    return r;
  };
  const StudyRunResult plain = run_once({});
  std::vector<std::size_t> generations;
  double last_best = 0.0;
  StudyRunOptions options;
  options.on_generation = [&](const optim::GenerationLog& g) {
    generations.push_back(g.generation);
    last_best = optim::statistics(g).best;
  };
  const StudyRunResult watched = run_once(options);
  EXPECT_EQ(watched.result, plain.result);
  ASSERT_GT(generations.size(), 10u);
  for (std::size_t i = 0; i < generations.size(); ++i) ASSERT_EQ(generations[i], i);
  const Json& d = plain.result["deterministic"];
  EXPECT_DOUBLE_EQ(last_best, d["energy"].get<double>());
  EXPECT_EQ(watched.report.generations, generations.size());
  EXPECT_EQ(plain.report.generations, generations.size());
  EXPECT_EQ(watched.report.evaluations + 1, d["evaluations"].get<std::size_t>());
  EXPECT_FALSE(watched.cancelled);

  optim::CancellationToken cancel;
  StudyRunOptions stopping;
  stopping.cancel = &cancel;
  stopping.on_progress = [&](const optim::GenerationLog& g, const studies::StudyReport&) {
    if (g.generation == 3) cancel.cancel();
  };
  const StudyRunResult stopped = run_once(stopping);
  EXPECT_TRUE(stopped.cancelled);
  EXPECT_EQ(stopped.report.generations, 5u);  // generations 0..3, then the final simplex
  EXPECT_EQ(stopped.result["deterministic"]["termination"], "Cancelled");
  EXPECT_LE(stopped.result["deterministic"]["energy"].get<double>(),
            plain.result["chord_length"]["energy"].get<double>());
}

// Checks a match-curvature-torsion study (a small NSGA-II on examples/studies/match-curvature-torsion-helix)
// stores its best compromise as a curve equal to the result's, with NSGA-II fronts in the progress.
TEST(StudyRun, CurvatureTorsionStoresCompromise) {
  Document doc;
  Json study = Json::parse(R"({"format": "hula-study", "version": 1, "study": "match-curvature-torsion", "seed": 1,
    "points": [[0, 0, 0], [10.310565, 6.30983, 5.526548], [5.177853, 18.99017, 9.653096],
               [-5.277853, 18.59017, 14.279645], [-10.010565, 6.20983, 20.706193]],
    "lower": [[0, 0, 0], [3, 3, 3], [3, 3, 3], [3, 3, 3], [3, 3, 3]],
    "upper": [[0, 0, 0], [3, 3, 3], [3, 3, 3], [3, 3, 3], [3, 3, 3]],
    "start_tangent": [1, 0, 0], "end_tangent": [3.09017, -9.510565, 4], "samples": 50,
    "nsga2": {"population": 20, "generations": 4}, "polish": false})");
  const Json helix = Json::parse(R"([[0, 0, 0], [9.510565, 6.90983, 5.026548], [5.877853, 18.09017, 10.053096],
    [-5.877853, 18.09017, 15.079645], [-9.510565, 6.90983, 20.106193]])");
  study["target"] = Json::object({{"of_points", helix}});
  study["torsion_target"] = Json::object({{"of_points", helix}});
  std::size_t objectives = 0;
  StudyRunOptions options;
  options.on_generation = [&](const optim::GenerationLog& g) { objectives = g.objectives; };
  StudyRunResult r;
  doc.transact("run", [&](Edit& e) { r = run_study(e, study, ".", options); }).throw_if_failed();
  EXPECT_EQ(objectives, 2u);
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_EQ(io::curve_to_json(doc.get(r.curves[0]).curve()), r.result["compromise"]["curve"]);
  // Every front member's curve passes through its points at their chord-length parameters, and κ, τ taken
  // from that curve's own derivatives (κ = |C' × C''| / |C'|³, τ = (C' × C'') · C''' / |C' × C''|²) at the
  // study's abscissae give back its two errors against the study's targets (the workbench previews and
  // applies these curves).
  const io::TorsionMatchStudyFile file = io::torsion_match_study_from_json(
      io::parse_study_json(r.result["study"].dump(), "match-curvature-torsion"), io::confined_to("."));
  const studies::CurvatureMatch match(file.study.setup);
  const std::vector<double>& u = match.sampler().abscissae();
  ASSERT_FALSE(r.result["front"].empty());
  for (const char* set : {"front", "nsga2_front"})
    for (const Json& m : r.result[set]) {
      const nurbs::NurbsCurve c = io::curve_from_json(m["curve"]).nurbs();
      const nurbs::Interval d = c.domain();
      std::vector<Vec3> pts;
      for (const Json& p : m["points"]) pts.push_back({p[0].get<double>(), p[1].get<double>(), p[2].get<double>()});
      ASSERT_EQ(pts.size(), 5u);
      std::vector<double> chord{0.0};
      for (std::size_t k = 1; k < pts.size(); ++k) chord.push_back(chord.back() + norm(pts[k] - pts[k - 1]));
      for (std::size_t k = 0; k < pts.size(); ++k)
        EXPECT_LT(norm(c.evaluate(d.start + d.length() * chord[k] / chord.back()) - pts[k]), 1e-9) << set << k;
      double kappa = 0.0, tau = 0.0;
      std::size_t defined = 0;
      for (std::size_t i = 0; i < u.size(); ++i) {
        const std::vector<Vec3> D = c.derivatives(d.start + u[i] * d.length(), 3);
        const Vec3 b = cross(D[1], D[2]);
        const double s = norm(D[1]);
        kappa += std::abs(norm(b) / (s * s * s) - match.target_samples()[i]);
        if (norm(b) <= 1e-12 * s * s * s) continue;
        tau += std::abs(dot(b, D[3]) / dot(b, b) - match.torsion_target_samples()[i]);
        ++defined;
      }
      EXPECT_NEAR(kappa / static_cast<double>(u.size()), m["curvature"].get<double>(), 1e-9) << set;
      EXPECT_NEAR(tau / static_cast<double>(defined), m["torsion"].get<double>(), 1e-9) << set;
    }
}

// Checks an edit-projection study whose original curve is a document entity (examples/studies/edit-projection):
// the stored rebuilt curve takes x and z from the edited curve and y from the original at the same normalised
// parameter (thesis 8.1), checked at u = 0.37 against both input curves evaluated directly.
TEST(StudyRun, EditProjectionOfAnEntity) {
  Document doc;
  const curve::Curve original = io::curve_from_json(Json::parse(
      R"({"kind": "interpolated", "points": [[0, 0, 0], [2, 1.5, 0.5], [4, 2, 1.5], [6, 1, 2.5], [8, 0, 3]]})"));
  Label c;
  doc.transact("add", [&](Edit& e) { c = e.add_curve(original, {.name = "spine"}); }).throw_if_failed();
  Json study = Json::parse(R"({"format": "hula-study", "version": 1, "study": "edit-projection", "plane": "zx",
    "edited": {"kind": "interpolated", "parameterisation": "uniform",
               "points": [[0, 0, 0], [2.5, 0, 1.2], [4, 0, 1], [5.5, 0, 2.6], [8, 0, 3]]}})");
  const curve::Curve edited = io::curve_from_json(study["edited"]);
  study["curve"] = Json::object({{"entity", c.value}});
  StudyRunResult r;
  doc.transact("run", [&](Edit& e) { r = run_study(e, study, "."); }).throw_if_failed();
  ASSERT_EQ(r.curves.size(), 1u);
  const nurbs::NurbsCurve& rebuilt = doc.get(r.curves[0]).curve().nurbs();
  const auto at = [](const nurbs::NurbsCurve& k, double u) {
    const nurbs::Interval d = k.domain();
    return k.evaluate(d.start + u * d.length());
  };
  const Vec3 p = at(rebuilt, 0.37), o = at(original.nurbs(), 0.37), q = at(edited.nurbs(), 0.37);
  EXPECT_NEAR(p.x, q.x, 1e-9);
  EXPECT_NEAR(p.z, q.z, 1e-9);
  EXPECT_NEAR(p.y, o.y, 1e-9);
  EXPECT_EQ(doc.get(r.curves[0]).provenance()->inputs, (std::vector<Label>{r.study, c}));
  EXPECT_EQ(r.result["plane"], "zx");
}

// Runs examples/studies/<name> in a document and with the CLI (`hula <command> FILE`); returns the run and
// the CLI's output without its log member (the --log path; the run's seed and threads are in both).
std::pair<StudyRunResult, Json> run_both(Document& doc, const std::string& command, const std::string& name) {
  const std::filesystem::path file = std::filesystem::path(HULA_EXAMPLES_DIR) / name;
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  StudyRunResult r;
  doc.transact("run", [&](Edit& e) { r = run_study(e, Json::parse(text.str()), file.parent_path()); })
      .throw_if_failed();
  const hula::testing::ProcessResult cli = hula::testing::run_process(HULA_CLI_PATH, {command, file.string()});
  EXPECT_EQ(cli.exit_code, 0) << cli.err;
  Json printed = Json::parse(cli.out);
  printed.erase("log");
  return {r, printed};
}

// Checks a fin-compound projection edit (examples/studies/fin-compound-edit.json) stores exactly what
// `hula fin-compound` prints (bit for bit: deterministic) and the rebuilt 3-D curve as an entity.
TEST(StudyRun, FinCompoundEditMatchesTheCli) {
  Document doc;
  const auto [r, printed] = run_both(doc, "fin-compound", "fin-compound-edit.json");
  EXPECT_EQ(r.result.dump(), printed.dump());
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_EQ(io::curve_to_json(doc.get(r.curves[0]).curve()), r.result["edit"]["curve"]);
  EXPECT_EQ(doc.get(r.curves[0]).provenance()->operation, "study:fin-compound");
  EXPECT_EQ(doc.get(r.curves[0]).provenance()->inputs, (std::vector<Label>{r.study}));
  EXPECT_EQ(doc.get(r.study).study().runs[0].result_curves, r.curves);
}

// Checks an inverse Combescure study on a law curve (examples/studies/combescure-inverse.json) stores what
// `hula fin-compound` prints, the parent as the result curve, and a round trip back to the compound < 1e-6.
TEST(StudyRun, CombescureInverseMatchesTheCli) {
  Document doc;
  const auto [r, printed] = run_both(doc, "fin-compound", "combescure-inverse.json");
  EXPECT_EQ(r.result.dump(), printed.dump());
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_EQ(io::curve_to_json(doc.get(r.curves[0]).curve()), r.result["parent"]["curve"]);
  EXPECT_LT(r.result["parent"]["round_trip_deviation"].get<double>(), 1e-6);
}

// Checks a hermite edit (examples/studies/hermite-direction.json) stores what `hula hermite` prints and the
// edited curve, which passes through the spline's data points (the Hermite rebuild keeps the knots' points).
TEST(StudyRun, HermiteMatchesTheCli) {
  Document doc;
  const auto [r, printed] = run_both(doc, "hermite", "hermite-direction.json");
  EXPECT_EQ(r.result.dump(), printed.dump());
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_EQ(io::curve_to_json(doc.get(r.curves[0]).curve()), r.result["curve"]);
  EXPECT_EQ(doc.get(r.curves[0]).provenance()->operation, "study:hermite");
  const nurbs::NurbsCurve& c = doc.get(r.curves[0]).curve().nurbs();
  for (const Json& knot : r.result["after"]) {
    const Vec3 p = c.evaluate(knot["t"].get<double>());
    EXPECT_NEAR(p.x, knot["point"][0].get<double>(), 1e-9);
    EXPECT_NEAR(p.y, knot["point"][1].get<double>(), 1e-9);
  }
}

}  // namespace
}  // namespace hula::oli
