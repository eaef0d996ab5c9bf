// SPDX-License-Identifier: MIT
// The bounded job pool (jobs.hpp).
#include "hula/server/jobs.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <latch>
#include <new>

#include "hula/io/error_json.hpp"

namespace hula::server {

namespace {

// The nice value of a job thread: the lowest there is. Under SCHED_IDLE the scheduler ignores it,
// but tools show it, and the I/O priority of the thread follows the policy (idle class).
constexpr int kJobNice = 19;

// Puts the calling thread at the lowest scheduling priority Linux has (docs/server.md
// "Concurrency"): nice 19, then SCHED_IDLE, under which the kernel runs the thread only on a core
// no other thread wants and preempts it as soon as one wakes (an I/O thread with a request). Both
// only lower the priority, which needs no privilege. Returns what failed, or "" when both held.
std::string lower_thread_priority() {
  std::string failed;
  if (::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), kJobNice) != 0)
    failed = std::string("setpriority(nice ") + std::to_string(kJobNice) + "): " + std::strerror(errno);
  sched_param param{};
  param.sched_priority = 0;
  if (const int rc = ::pthread_setschedparam(::pthread_self(), SCHED_IDLE, &param); rc != 0)
    failed += (failed.empty() ? "" : "; ") + std::string("pthread_setschedparam(SCHED_IDLE): ") + std::strerror(rc);
  return failed;
}

// A cancelled job's thread goes back to SCHED_OTHER (keeping nice 19; an unprivileged process may do
// this for its own threads), so winding down to the next generation is not starved by every other
// busy thread of the machine. Best effort: if refused, the job still stops, only later.
void wind_down(pid_t thread) {
  if (thread == 0) return;
  sched_param param{};
  param.sched_priority = 0;
  (void)::sched_setscheduler(thread, SCHED_OTHER, &param);
}

}  // namespace

std::string_view job_state_name(JobState state) noexcept {
  switch (state) {
    case JobState::Queued:
      return "queued";
    case JobState::Running:
      return "running";
    case JobState::Done:
      return "done";
    case JobState::Failed:
      return "failed";
    case JobState::Cancelled:
      return "cancelled";
  }
  return "failed";
}

Job::Job(std::string id, std::string kind) : id_(std::move(id)), kind_(std::move(kind)) {}

JobState Job::state() const {
  std::lock_guard lock(mutex_);
  return state_;
}

Json Job::to_json() const {
  std::lock_guard lock(mutex_);
  Json j = Json::object();
  j["job"] = id_;
  j["kind"] = kind_;
  j["state"] = std::string(job_state_name(state_));
  j["report"] = outcome_.report;
  j["result"] = outcome_.result;
  j["error"] = error_;
  return j;
}

JobPool::JobPool(JobPoolOptions options) : options_(options) {
  if (options_.workers == 0) options_.workers = 1;
  // Every worker has lowered its priority (or said why not) before the pool takes a job.
  std::latch lowered(static_cast<std::ptrdiff_t>(options_.workers));
  for (std::size_t i = 0; i < options_.workers; ++i)
    workers_.emplace_back([this, &lowered] {
      std::string failed = lower_thread_priority();
      {
        std::lock_guard lock(mutex_);
        if (priority_error_.empty()) priority_error_ = std::move(failed);
      }
      lowered.count_down();
      worker();
    });
  lowered.wait();
}

std::string JobPool::priority_error() const {
  std::lock_guard lock(mutex_);
  return priority_error_;
}

JobPool::~JobPool() { shutdown(); }

std::shared_ptr<Job> JobPool::submit(std::string kind, JobWork work) {
  std::lock_guard lock(mutex_);
  if (stopping_) throw HttpError(503, "ShuttingDown", "the server is stopping and takes no new jobs");
  if (queue_.size() >= options_.queue_limit)
    throw HttpError(429, "TooManyJobs",
                    std::to_string(queue_.size()) + " jobs are already waiting for a worker (limit " +
                        std::to_string(options_.queue_limit) + "); retry when one has started");
  auto job = std::make_shared<Job>(std::to_string(next_id_++), std::move(kind));
  job->work_ = std::move(work);
  jobs_[job->id()] = job;
  queue_.push_back(job);
  wake_.notify_one();
  return job;
}

std::shared_ptr<Job> JobPool::find(const std::string& id) const {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  return it == jobs_.end() ? nullptr : it->second;
}

void JobPool::cancel(Job& job) {
  {
    std::lock_guard lock(mutex_);
    for (auto it = queue_.begin(); it != queue_.end(); ++it)
      if (it->get() == &job) {
        queue_.erase(it);
        break;
      }
  }
  bool was_queued = false;
  {
    std::lock_guard lock(job.mutex_);
    job.cancel_.cancel();
    was_queued = job.state_ == JobState::Queued;
    if (job.state_ == JobState::Running) wind_down(job.thread_);
  }
  if (was_queued) finish(job, JobState::Cancelled);
}

void JobPool::finish(Job& job, JobState state) {
  Json final_event;
  {
    std::lock_guard lock(job.mutex_);
    job.state_ = state;
    job.work_ = nullptr;
  }
  final_event = job.to_json();
  job.events_->append(job_state_name(state), final_event);
  job.events_->close();
  std::lock_guard lock(mutex_);
  finished_order_.push_back(job.id());
  while (finished_order_.size() > options_.keep_finished) {
    jobs_.erase(finished_order_.front());
    finished_order_.pop_front();
  }
}

void JobPool::worker() {
  while (true) {
    std::shared_ptr<Job> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopping, nothing left
      job = queue_.front();
      queue_.pop_front();
    }
    run(job);
  }
}

void JobPool::run(const std::shared_ptr<Job>& job) {
  JobWork work;
  {
    std::lock_guard lock(job->mutex_);
    if (job->state_ != JobState::Queued) return;
    job->state_ = JobState::Running;
    job->thread_ = ::gettid();
    work = job->work_;
  }
  // Again for every job: the last one on this thread may have been cancelled (wind_down).
  (void)lower_thread_priority();
  EventLog& events = *job->events_;
  JobContext context{job->cancel_, [&events](const Json& e) { events.append("generation", e); }};
  try {
    JobOutcome outcome = work(context);
    const bool cancelled = outcome.cancelled;
    {
      std::lock_guard lock(job->mutex_);
      job->outcome_ = std::move(outcome);
    }
    finish(*job, cancelled ? JobState::Cancelled : JobState::Done);
  } catch (const Error& e) {
    {
      std::lock_guard lock(job->mutex_);
      job->error_ = io::error_to_json(e)["error"];
    }
    finish(*job, JobState::Failed);
  } catch (const std::exception& e) {
    {
      std::lock_guard lock(job->mutex_);
      const bool out_of_memory = dynamic_cast<const std::bad_alloc*>(&e) != nullptr;
      Json err = Json::object();
      err["code"] = out_of_memory ? "OutOfMemory" : "InternalError";
      err["message"] = out_of_memory ? std::string(
                                           "out of memory: the job needs more memory than the server can "
                                           "allocate")
                                     : std::string(e.what());
      err["where"] = Json::object();
      job->error_ = std::move(err);
    }
    finish(*job, JobState::Failed);
  }
}

void JobPool::shutdown() {
  const std::lock_guard joining(shutdown_mutex_);
  std::deque<std::shared_ptr<Job>> queued;
  std::vector<std::shared_ptr<Job>> all;
  {
    std::lock_guard lock(mutex_);
    if (stopping_ && workers_.empty()) return;
    stopping_ = true;
    queued.swap(queue_);
    for (auto& [id, job] : jobs_) all.push_back(job);
  }
  for (auto& job : all) {
    std::lock_guard lock(job->mutex_);
    job->cancel_.cancel();
    if (job->state_ == JobState::Running) wind_down(job->thread_);
  }
  for (auto& job : queued) finish(*job, JobState::Cancelled);
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
  workers_.clear();
}

}  // namespace hula::server
