// SPDX-License-Identifier: MIT
// Optimisation problems as server jobs (problem_job.hpp).
#include "hula/server/problem_job.hpp"

#include <memory>
#include <utility>

#include "hula/oli/problem_run.hpp"

namespace hula::server {

JobWork problem_job(const Json& request) {
  const auto run = std::make_shared<const oli::ProblemRun>(oli::ProblemRun::from_json(request));
  return [run](JobContext& context) {
    oli::ProblemRunOutcome o = run->run(&context.cancel, [&context](Json event) { context.publish(std::move(event)); });
    JobOutcome out;
    out.result = std::move(o.result);
    out.report = std::move(o.report);
    out.cancelled = o.cancelled;
    return out;
  };
}

}  // namespace hula::server
