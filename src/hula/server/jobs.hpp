// SPDX-License-Identifier: MIT
// Long computations of the server (optimisation runs, studies) as jobs on a
// bounded pool of worker threads, never on the HTTP threads. A job is
// queued, running, then done, failed or cancelled; its events (one per
// generation, then the final state) go to an EventLog that any number of SSE
// clients follow. Cancelling a running job sets its CancellationToken: the
// algorithm stops at the next generation and the job keeps the best so far.
// The worker threads run at the lowest scheduling priority (SCHED_IDLE and
// nice 19 on Linux), so a request never waits for a core a job holds.
#pragma once

#include <sys/types.h>

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "hula/oli/problem_run.hpp"
#include "hula/server/events.hpp"
#include "hula/server/http.hpp"

namespace hula::server {

enum class JobState { Queued, Running, Done, Failed, Cancelled };

/// "queued", "running", "done", "failed", "cancelled".
[[nodiscard]] std::string_view job_state_name(JobState state) noexcept;

/// What a job's work returns: its result and report (JSON), and whether it stopped on cancellation.
struct JobOutcome {
  Json result = nullptr;
  Json report = nullptr;
  bool cancelled = false;
};

/// What a job's work sees while it runs.
struct JobContext {
  /// Set by DELETE /api/jobs/{id} or by the server's shutdown; pass it to the algorithm.
  const oli::CancellationToken& cancel;
  /// Publishes one progress event ("generation") to the job's subscribers.
  std::function<void(const Json&)> publish;
};

/// The work of a job; runs on a pool thread. A hula::Error or other exception makes the job failed
/// with that error.
using JobWork = std::function<JobOutcome(JobContext&)>;

class Job {
 public:
  Job(std::string id, std::string kind);

  [[nodiscard]] const std::string& id() const noexcept { return id_; }
  [[nodiscard]] std::shared_ptr<EventLog> events() const noexcept { return events_; }
  /// {"job", "kind", "state", "report", "result", "error"}.
  [[nodiscard]] Json to_json() const;
  [[nodiscard]] JobState state() const;

 private:
  friend class JobPool;
  std::string id_;
  std::string kind_;
  mutable std::mutex mutex_;
  JobState state_ = JobState::Queued;
  JobOutcome outcome_{};
  Json error_ = nullptr;
  oli::CancellationToken cancel_;
  /// The thread running the job (Linux thread id), 0 before it starts.
  pid_t thread_ = 0;
  JobWork work_;
  std::shared_ptr<EventLog> events_ = std::make_shared<EventLog>();
};

struct JobPoolOptions {
  /// Worker threads, ≥ 1.
  std::size_t workers = 1;
  /// Jobs allowed to wait for a worker; one more is refused with 429.
  std::size_t queue_limit = 16;
  /// Finished jobs kept for GET; the oldest finished are forgotten past this.
  std::size_t keep_finished = 256;
};

class JobPool {
 public:
  explicit JobPool(JobPoolOptions options);
  ~JobPool();
  JobPool(const JobPool&) = delete;
  JobPool& operator=(const JobPool&) = delete;

  /// Queues a job.
  /// @throws HttpError(429, "TooManyJobs") when queue_limit jobs are waiting
  /// @throws HttpError(503, "ShuttingDown") after shutdown()
  std::shared_ptr<Job> submit(std::string kind, JobWork work);

  /// The job with this id, or nullptr.
  [[nodiscard]] std::shared_ptr<Job> find(const std::string& id) const;

  /// Cancels a job: a queued one ends cancelled at once (no result), a running one stops at its
  /// next generation keeping the best so far (its thread leaves SCHED_IDLE for SCHED_OTHER at nice
  /// 19 until then); a finished one is left as it is.
  void cancel(Job& job);

  /// Cancels every job, waits for the running ones to store their outcome and joins the workers.
  /// Safe to call from several threads at once (Server::stop from any thread while Server::run ends):
  /// a second caller waits for the first and returns.
  void shutdown();

  /// Why a worker thread could not lower its scheduling priority (SCHED_IDLE, nice 19), or "" when
  /// every worker runs at it (known once the constructor returns).
  [[nodiscard]] std::string priority_error() const;

 private:
  void worker();
  void run(const std::shared_ptr<Job>& job);
  void finish(Job& job, JobState state);
  JobPoolOptions options_;
  mutable std::mutex mutex_;
  /// Held through shutdown(), so that two callers never join the same worker.
  std::mutex shutdown_mutex_;
  std::condition_variable wake_;
  std::deque<std::shared_ptr<Job>> queue_;
  std::map<std::string, std::shared_ptr<Job>> jobs_;
  std::deque<std::string> finished_order_;
  std::size_t next_id_ = 1;
  bool stopping_ = false;
  std::string priority_error_;
  std::vector<std::thread> workers_;
};

}  // namespace hula::server
