// SPDX-License-Identifier: MIT
// Jobs: POST /api/jobs {"problem": ...} → 202 {"job": id, ...};
// GET /api/jobs/{id} → state, report, result, error; GET /api/jobs/{id}/events
// → Server-Sent Events (one "generation" event per generation, then one of
// "done", "failed", "cancelled" carrying the job); DELETE /api/jobs/{id}
// cancels, keeping the best so far (jobs.hpp, problem_job.hpp).
// POST /api/jobs {"document": name, "study": study file} runs the study in the
// three phases of oli (study_run.hpp): its entity references are resolved
// under the document's read lock, the study computes holding no lock (the
// document stays readable and editable), and one transaction under the writer
// lock stores the study entity, its run and its result curves — or nothing, if
// it fails. A run whose inputs changed meanwhile is stored as computed from the
// inputs as read at start (docs/server.md "Study jobs").
// Its events are the problem job's plus "study" (the kind), with generations
// counted across the study's optimiser runs (docs/server.md "Study jobs");
// cancelling it stores the best so far.
#include <chrono>

#include "hula/io/json_read.hpp"
#include "hula/io/run_report_json.hpp"
#include "hula/oli/study_run.hpp"
#include "hula/server/problem_job.hpp"
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

namespace {

std::shared_ptr<Job> find_job(JobPool& jobs, const Request& request) {
  auto job = jobs.find(request.params.at(0));
  if (!job) throw HttpError(404, "NotFound", "no job '" + request.params.at(0) + "'");
  return job;
}

// The work of a study job: prepare (read lock), compute (no lock), commit (writer lock, one transaction).
JobWork study_job(std::shared_ptr<OpenDocument> doc, Json study, std::filesystem::path workspace) {
  return [doc = std::move(doc), study = std::move(study), workspace = std::move(workspace)](JobContext& context) {
    oli::StudyRunOptions options;
    options.cancel = &context.cancel;
    // Generations and evaluations run on across the study's optimiser runs (each restarts at 0).
    options.on_progress = [&](const optim::GenerationLog& g, const studies::StudyReport& so_far) {
      Json e = io::generation_event_json(g, so_far.seconds);
      e["generation"] = so_far.generations - 1;
      e["evaluations"] = so_far.evaluations;
      e["study"] = so_far.kind;
      context.publish(e);
    };
    oli::PreparedStudy prepared = doc->read([&](const oli::Document& d) { return oli::prepare_study(d, study); });
    oli::ComputedStudy computed = oli::compute_study(std::move(prepared), workspace, options);
    oli::StudyRunResult run;
    const oli::Outcome o = doc->write([&](oli::Document& d) {
      return d.transact("run study", [&](oli::Edit& e) { run = oli::commit_study(e, std::move(computed)); });
    });
    o.throw_if_failed();
    JobOutcome out;
    out.cancelled = run.cancelled;
    out.report = io::study_report_to_json(run.report);
    Json curves = Json::array();
    for (const oli::Label l : run.curves) curves.push_back(l.value);
    out.result = Json::object();
    out.result["document"] = doc->name();
    out.result["study"] = run.study.value;
    out.result["curves"] = std::move(curves);
    out.result["revision"] = o.revision;
    out.result["result"] = run.result;
    return out;
  };
}

}  // namespace

void add_jobs(Router& router, const Context& context) {
  JobPool& jobs = context.jobs;
  DocumentRegistry& docs = context.documents;
  router.add("POST", "/api/jobs", [&jobs, &docs, workspace = context.workspace](const Request& request) {
    const Json body = request.json();
    if (body.is_object() && body.contains("document")) {
      namespace json = io::json;
      json::reject_unknown_members(body, json::JsonPath(), {"document", "study"});
      const std::string name =
          json::get_string(json::require_member(body, json::JsonPath(), "document"), json::root_path("document"));
      const Json& study = json::require_member(body, json::JsonPath(), "study");
      if (!study.is_object()) json::type_error(study, json::root_path("study"), "a study file object");
      const auto job = jobs.submit("study", study_job(docs.get(name), study, workspace));
      return json_response(202, job->to_json());
    }
    if (!body.is_object() || !body.contains("problem"))
      throw Error(Errc::ParseError,
                  "request body: a job needs a \"problem\" member (an optimisation problem) or \"document\" and "
                  "\"study\"",
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
