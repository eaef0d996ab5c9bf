// SPDX-License-Identifier: MIT
// An optimisation problem run for a front end that holds no solver (the
// server's POST /api/jobs {"problem": ...}): the request read and checked up
// front, then run by optim::solve with one progress event per generation and
// a cancellation flag. The problem is in the problem-file format
// (docs/formats.md, io/problem_file.hpp); the algorithm is named as every
// door names one (optim::solver_from_name) and must be a population algorithm
// (ga-real, ga-binary, nsga2: progress per generation). The result is the
// best solution (one objective) or the final front (NSGA-II), as `hula
// optimise` prints them, with the run report (io/run_report_json.hpp).
#pragma once

#include <functional>
#include <memory>

#include "hula/io/json_read.hpp"
#include "hula/optim/run_report.hpp"

namespace hula::oli {

using Json = io::json::Json;
/// The flag that ends a run cleanly (optim::CancellationToken), for front ends that include no solver.
using CancellationToken = optim::CancellationToken;

/// What a problem run gives: {"best": solution} or {"front": [solutions]} with solutions {"variables",
/// "objectives", "violation"}, the report, and whether the cancellation flag ended it.
struct ProblemRunOutcome {
  Json result = Json::object();
  Json report = Json::object();
  bool cancelled = false;
};

/// A problem run request, read and checked, ready to run (cheap to copy: it shares its state).
class ProblemRun {
 public:
  /// Reads {"problem": {...}, "algorithm"?: "ga-real" (default) | "ga-binary" | "nsga2", "population"?: n,
  /// "generations"?: n in [1, 100000], "seed"?: n}. Everything that can be checked before running is
  /// checked here (the options' validate, the objective count the algorithm takes).
  /// @throws hula::Error(Errc::ParseError) for an unknown or mistyped member (naming it); the errors of
  ///   io::problem_from_json, optim::solver_from_name and the algorithm's Options::validate;
  ///   hula::Error(Errc::InvalidOption) naming "algorithm" for another algorithm or the wrong objective count
  [[nodiscard]] static ProblemRun from_json(const Json& request);

  /// Runs it: `on_event` receives io::generation_event_json of each generation (on the running thread);
  /// once `cancel` is set the run stops at the next generation with its best so far.
  /// @throws the algorithm's errors (NumericalFailure when nothing could be evaluated)
  [[nodiscard]] ProblemRunOutcome run(const CancellationToken* cancel,
                                      const std::function<void(Json event)>& on_event) const;

  struct State;

 private:
  explicit ProblemRun(std::shared_ptr<const State> state) : state_(std::move(state)) {}
  std::shared_ptr<const State> state_;
};

}  // namespace hula::oli
