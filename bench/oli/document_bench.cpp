// SPDX-License-Identifier: MIT
// The document's hot paths: a control-point move
// on a 100-point curve as an in-memory transaction (target ≤ 20 µs) and
// committed to disk (WAL, synchronous=NORMAL; ≤ 2 ms), undo and redo on disk
// (≤ 1 ms each), and opening a document of 10,000 curves of 50 control points
// (≤ 0.5 s, file ≤ 1.5× the raw doubles). A study run's cost against the cost
// of storing it with its run log (every individual of every generation): a
// match-curvature GA of 200 generations × 100 individuals computed, then
// committed to a document on disk, shown as JSON (`hula doc show`'s
// answer) and the document reopened (target: storing ≤ 0.2× the run).
// Results: docs/benchmarks.md.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "hula/curve/curve.hpp"
#include "hula/nurbs/knot_vector.hpp"
#include "hula/oli/document.hpp"
#include "hula/oli/study_run.hpp"

namespace {

using namespace hula;

curve::Curve cubic(std::size_t n) {
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < n; ++i)
    points.emplace_back(static_cast<double>(i), static_cast<double>(i % 3), 0.5 * static_cast<double>(i));
  return curve::Curve(nurbs::NurbsCurve(nurbs::KnotVector::uniform_clamped(n, 3), std::move(points)));
}

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("hula-bench-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir / name;
}

// The undo limit keeps memory bounded over millions of iterations; it does not change the per-step cost.
constexpr std::size_t kUndoLimit = 100;

void move_loop(benchmark::State& state, oli::Document& doc, oli::Label label) {
  std::size_t i = 0;
  for (auto _ : state) {
    const double x = static_cast<double>(i % 17);
    const oli::Outcome out = doc.transact("move point", [&](oli::Edit& e) { e.move_point(label, 50, {x, 1.0, 2.0}); });
    benchmark::DoNotOptimize(out.revision);
    ++i;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

void BM_oli_move_in_memory(benchmark::State& state) {
  oli::Document doc({.undo_limit = kUndoLimit});
  oli::Label label;
  doc.transact("add", [&](oli::Edit& e) { label = e.add_curve(cubic(static_cast<std::size_t>(state.range(0)))); });
  move_loop(state, doc, label);
}
BENCHMARK(BM_oli_move_in_memory)->Arg(100)->Unit(benchmark::kMicrosecond);

void BM_oli_move_commit(benchmark::State& state) {
  const auto path = scratch("move.hula");
  {
    oli::Document doc = oli::Document::create(path, {.undo_limit = kUndoLimit}, true);
    oli::Label label;
    doc.transact("add", [&](oli::Edit& e) { label = e.add_curve(cubic(static_cast<std::size_t>(state.range(0)))); });
    move_loop(state, doc, label);
  }
  std::filesystem::remove_all(path.parent_path());
}
BENCHMARK(BM_oli_move_commit)->Arg(100)->Unit(benchmark::kMicrosecond);

// One iteration = one undo or one redo (alternating), on disk.
void BM_oli_undo_redo_commit(benchmark::State& state) {
  const auto path = scratch("undo.hula");
  {
    oli::Document doc = oli::Document::create(path, {}, true);
    oli::Label label;
    doc.transact("add", [&](oli::Edit& e) { label = e.add_curve(cubic(static_cast<std::size_t>(state.range(0)))); });
    doc.transact("move point", [&](oli::Edit& e) { e.move_point(label, 50, {7.0, 1.0, 2.0}); });
    bool undo = true;
    for (auto _ : state) {
      const oli::Outcome out = undo ? doc.undo() : doc.redo();
      if (!out.committed) state.SkipWithError(out.error_message.c_str());
      undo = !undo;
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  }
  std::filesystem::remove_all(path.parent_path());
}
BENCHMARK(BM_oli_undo_redo_commit)->Arg(100)->Unit(benchmark::kMicrosecond);

// Opening (loading and decoding every entity) a document of range(0) curves of 50 control points.
void BM_oli_open(benchmark::State& state) {
  const auto path = scratch("open.hula");
  const auto count = static_cast<std::size_t>(state.range(0));
  constexpr std::size_t kPoints = 50;
  {
    oli::Document doc = oli::Document::create(path, {}, true);
    doc.transact("add many",
                 [&](oli::Edit& e) {
                   for (std::size_t i = 0; i < count; ++i) (void)e.add_curve(cubic(kPoints));
                 })
        .throw_if_failed();
  }
  for (auto _ : state) {
    oli::Document doc = oli::Document::open(path, oli::OpenMode::ReadOnly);
    benchmark::DoNotOptimize(doc.size());
  }
  // Raw doubles of one curve: 50 control points × 3 coordinates + 54 knots.
  const double raw = static_cast<double>(count * (kPoints * 3 + kPoints + 4) * sizeof(double));
  const double control_only = static_cast<double>(count * kPoints * 3 * sizeof(double));
  const double file = static_cast<double>(std::filesystem::file_size(path));
  state.counters["file_MB"] = file / 1e6;
  state.counters["file_over_raw"] = file / raw;
  state.counters["file_over_control_points"] = file / control_only;
  std::filesystem::remove_all(path.parent_path());
}
BENCHMARK(BM_oli_open)->Arg(10000)->Unit(benchmark::kMillisecond)->Iterations(3);

// The study of the run-log benchmarks: thesis example 1 (match-curvature-example1.json) with a GA of
// range(0) generations × range(1) individuals on one thread.
oli::Json study_setup(const benchmark::State& state) {
  oli::Json setup = oli::Json::parse(R"({
    "format": "hula-study", "version": 1, "study": "match-curvature", "seed": 1, "threads": 1,
    "points": [[0, 0], [5, 20], [40, 0]], "lower": [[0, 0], [30, 30], [0, 0]], "upper": [[0, 0], [35, 30], [0, 0]],
    "target": {"of_points": [[0, 0], [5, 20], [40, 0]], "mirror": true}, "samples": 200, "method": "ga",
    "ga": {"algorithm": "binary", "boost_start": 3, "boost_end": 5, "crossover_probability": 1.0,
           "mutation_probability": 0.01, "precision": 0.001}})");
  setup["ga"]["generations"] = state.range(0);
  setup["ga"]["population"] = state.range(1);
  return setup;
}

oli::ComputedStudy compute(const benchmark::State& state, const oli::Document& doc) {
  return oli::compute_study(oli::prepare_study(doc, study_setup(state)), {});
}

// Running the study without storing it (what storing it is compared with).
void BM_oli_study_run(benchmark::State& state) {
  const oli::Document doc;
  for (auto _ : state) {
    oli::ComputedStudy computed = compute(state, doc);
    benchmark::DoNotOptimize(computed.run.seed);
  }
}

// Storing one computed run (study entity, run with its log, result curve) in a new document on disk.
void BM_oli_study_store(benchmark::State& state) {
  const auto path = scratch("study.hula");
  const oli::ComputedStudy computed = compute(state, oli::Document());
  for (auto _ : state) {
    state.PauseTiming();
    std::filesystem::remove(path);
    oli::Document doc = oli::Document::create(path, {}, true);
    oli::ComputedStudy copy = computed;
    state.ResumeTiming();
    doc.transact("run study", [&](oli::Edit& e) { (void)oli::commit_study(e, std::move(copy)); }).throw_if_failed();
  }
  state.counters["file_MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  std::filesystem::remove_all(path.parent_path());
}

// The study entity as JSON with its log (`hula doc show`, GET .../entities/{label}, Python Document.show).
void BM_oli_study_show(benchmark::State& state) {
  oli::Document doc;
  oli::Label study;
  doc.transact("run study", [&](oli::Edit& e) { study = oli::commit_study(e, compute(state, doc)).study; })
      .throw_if_failed();
  for (auto _ : state) {
    const oli::Json shown = oli::entity_to_json(doc.get(study));
    benchmark::DoNotOptimize(shown.size());
  }
}

// Opening a document holding one such run (decoding its log).
void BM_oli_study_open(benchmark::State& state) {
  const auto path = scratch("study-open.hula");
  {
    oli::Document doc = oli::Document::create(path, {}, true);
    doc.transact("run study", [&](oli::Edit& e) { (void)oli::commit_study(e, compute(state, doc)); }).throw_if_failed();
  }
  for (auto _ : state) {
    oli::Document doc = oli::Document::open(path, oli::OpenMode::ReadOnly);
    benchmark::DoNotOptimize(doc.size());
  }
  std::filesystem::remove_all(path.parent_path());
}

BENCHMARK(BM_oli_study_run)->Args({200, 100})->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_oli_study_store)->Args({200, 100})->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_oli_study_show)->Args({200, 100})->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_oli_study_open)->Args({200, 100})->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
