// SPDX-License-Identifier: MIT
// Unit tests of the job pool's scheduling priority (server/jobs.hpp): what the kernel reports for a
// worker thread, read from /proc/self/task/<tid>/stat and sched_getscheduler, not timed.
#include "hula/server/jobs.hpp"

#include <gtest/gtest.h>
#include <sched.h>
#include <unistd.h>

#include <atomic>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace hula::server {
namespace {

// The fields of /proc/self/task/<tid>/stat after the command name, so fields[0] is field 3 (state)
// of proc(5) and field k is fields[k - 3].
std::vector<std::string> task_stat(pid_t tid) {
  std::ifstream in("/proc/self/task/" + std::to_string(tid) + "/stat");
  std::string text;
  std::getline(in, text);
  std::istringstream rest(text.substr(text.rfind(')') + 1));
  std::vector<std::string> fields;
  for (std::string f; rest >> f;) fields.push_back(f);
  return fields;
}
int nice_of(const std::vector<std::string>& stat) { return std::stoi(stat.at(19 - 3)); }
int policy_of(const std::vector<std::string>& stat) { return std::stoi(stat.at(41 - 3)); }

// The thread id a job ran on, once it has finished.
pid_t job_thread(JobPool& pool) {
  std::atomic<pid_t> tid{0};
  const auto job = pool.submit("probe", [&tid](JobContext&) {
    tid = ::gettid();
    return JobOutcome{};
  });
  while (job->state() != JobState::Done) std::this_thread::yield();
  return tid.load();
}

// checks every job runs on a thread the kernel schedules as SCHED_IDLE with nice 19 (proc(5) fields
// 41 and 19, and sched_getscheduler), while the thread that made the pool keeps its own priority
// checks two threads shutting the pool down at once (Server::stop from the caller's thread while Server::run
// winds down) both return: each worker is joined once
TEST(JobPool, ConcurrentShutdownsBothReturn) {
  for (int round = 0; round < 50; ++round) {
    JobPool pool(JobPoolOptions{.workers = 2});
    std::atomic<int> done{0};
    std::thread other([&] {
      pool.shutdown();
      ++done;
    });
    pool.shutdown();
    ++done;
    other.join();
    EXPECT_EQ(done.load(), 2);
  }
}

TEST(JobPool, WorkersRunAtTheLowestSchedulingPriority) {
  const std::vector<std::string> own_before = task_stat(::gettid());
  JobPool pool(JobPoolOptions{.workers = 2});
  EXPECT_EQ(pool.priority_error(), "");
  for (int k = 0; k < 4; ++k) {
    const pid_t tid = job_thread(pool);
    ASSERT_GT(tid, 0);
    ASSERT_NE(tid, ::gettid());
    const std::vector<std::string> stat = task_stat(tid);
    EXPECT_EQ(policy_of(stat), SCHED_IDLE) << "thread " << tid;
    EXPECT_EQ(nice_of(stat), 19) << "thread " << tid;
    EXPECT_EQ(::sched_getscheduler(tid), SCHED_IDLE) << "thread " << tid;
  }
  const std::vector<std::string> own = task_stat(::gettid());
  EXPECT_EQ(policy_of(own), policy_of(own_before));
  EXPECT_EQ(nice_of(own), nice_of(own_before));
}

// checks a cancelled running job winds down under SCHED_OTHER at nice 19 (proc(5) fields 41 and 19),
// and the next job on the same worker is back at SCHED_IDLE
TEST(JobPool, CancelledJobWindsDownAtNice19ThenNextJobIsIdleAgain) {
  JobPool pool(JobPoolOptions{.workers = 1});
  std::atomic<pid_t> tid{0};
  const auto job = pool.submit("spin", [&tid](JobContext& context) {
    tid = ::gettid();
    while (!context.cancel.is_cancelled()) std::this_thread::yield();
    return JobOutcome{.cancelled = true};
  });
  while (tid.load() == 0) std::this_thread::yield();
  EXPECT_EQ(policy_of(task_stat(tid)), SCHED_IDLE);
  pool.cancel(*job);
  while (job->state() != JobState::Cancelled) std::this_thread::yield();
  const std::vector<std::string> stat = task_stat(tid);
  EXPECT_EQ(policy_of(stat), SCHED_OTHER);
  EXPECT_EQ(nice_of(stat), 19);
  const pid_t next = job_thread(pool);
  EXPECT_EQ(next, tid.load());
  EXPECT_EQ(policy_of(task_stat(next)), SCHED_IDLE);
}

}  // namespace
}  // namespace hula::server
