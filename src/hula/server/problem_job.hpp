// SPDX-License-Identifier: MIT
// The job of POST /api/jobs {"problem": ...}: an optimisation problem run
// (oli::ProblemRun: the problem in the problem-file format, a Flexo
// population algorithm named as every door names one) with one progress event
// per generation ({"generation", "evaluations", "best", "front"?, "elapsed"},
// io::generation_event_json). The result is the best solution (GA) or the
// final front (NSGA-II), as `hula optimise` prints them.
#pragma once

#include "hula/server/jobs.hpp"

namespace hula::server {

/// Reads the job request and returns its work, ready for JobPool::submit. Everything that can be
/// checked before running is checked here (oli::ProblemRun::from_json), so bad input is refused with
/// 400 rather than a failed job.
/// @param request {"problem": {...}, "algorithm"?: "ga-real" (default) | "ga-binary" | "nsga2",
///   "population"?: n, "generations"?: n in [1, 100000], "seed"?: n}
/// @throws as oli::ProblemRun::from_json
[[nodiscard]] JobWork problem_job(const Json& request);

}  // namespace hula::server
