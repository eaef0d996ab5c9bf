// SPDX-License-Identifier: MIT
// Jobs: POST /api/jobs {"problem": ...} → 202 {"job": id, ...};
// GET /api/jobs/{id} → state, report, result, error; GET /api/jobs/{id}/events
// → Server-Sent Events (one "generation" event per generation, then one of
// "done", "failed", "cancelled" carrying the job); DELETE /api/jobs/{id}
// cancels, keeping the best so far (jobs.hpp, problem_job.hpp).
#include "hula/io/json_read.hpp"
#include "hula/server/problem_job.hpp"
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

namespace {

std::shared_ptr<Job> find_job(JobPool& jobs, const Request& request) {
  auto job = jobs.find(request.params.at(0));
  if (!job) throw HttpError(404, "NotFound", "no job '" + request.params.at(0) + "'");
  return job;
}

}  // namespace

void add_jobs(Router& router, const Context& context) {
  JobPool& jobs = context.jobs;
  router.add("POST", "/api/jobs", [&jobs](const Request& request) {
    const Json body = request.json();
    if (!body.is_object() || !body.contains("problem"))
      throw Error(Errc::ParseError, "request body: a job needs a \"problem\" member (an optimisation problem)",
                  ErrorWhere{.field = "problem"});
    JobWork work = problem_job(body);
    const auto job = jobs.submit("problem", std::move(work));
    return json_response(202, job->to_json());
  });
  router.add("GET", "/api/jobs/{id}",
             [&jobs](const Request& request) { return json_response(200, find_job(jobs, request)->to_json()); });
  router.add("GET", "/api/jobs/{id}/events", [&jobs](const Request& request) {
    Response r;
    r.events = find_job(jobs, request)->events();
    return r;
  });
  router.add("DELETE", "/api/jobs/{id}", [&jobs](const Request& request) {
    const auto job = find_job(jobs, request);
    jobs.cancel(*job);
    return json_response(200, job->to_json());
  });
}

}  // namespace hula::server::routes
