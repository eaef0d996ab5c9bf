// SPDX-License-Identifier: MIT
// The job of POST /api/jobs {"problem": ...}: an optimisation problem in the
// problem-file format (docs/formats.md, io/problem_file.hpp) solved by a
// Flexo algorithm (real- or binary-coded GA, NSGA-II) with one progress event
// per generation: {"generation", "evaluations", "best": objectives of the
// best individual, "front": first-front objectives (NSGA-II), "elapsed"
// seconds}. The result is the best solution (GA) or the final front
// (NSGA-II), as `hula optimise` prints them.
#pragma once

#include "hula/optim/run_log.hpp"
#include "hula/server/jobs.hpp"

namespace hula::server {

/// The progress event of one generation: {"generation", "evaluations", "best": objectives of the best
/// individual (feasible first, then smallest first objective; null for an undefined value), "front"
/// (several objectives: the first front's objectives), "elapsed": `elapsed` seconds}.
[[nodiscard]] Json generation_event(const optim::GenerationLog& generation, double elapsed);

/// Reads the job request and returns its work, ready for JobPool::submit. Everything that can be
/// checked before running is checked here, so bad input is refused with 400 rather than a failed job.
/// @param request {"problem": {...}, "algorithm"?: "ga-real" (default) | "ga-binary" | "nsga2",
///   "population"?: n, "generations"?: n in [1, 100000], "seed"?: n}
/// @throws hula::Error(Errc::ParseError) for an unknown member or a mistyped one (naming it), and
///   the errors of io::parse_problem_json and of the algorithm's Options::validate
[[nodiscard]] JobWork problem_job(const Json& request);

}  // namespace hula::server
