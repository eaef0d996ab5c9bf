// SPDX-License-Identifier: MIT
// Unit tests of the SSE event log (server/events.hpp) and the job pool (server/jobs.hpp).
#include "hula/server/events.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "hula/server/jobs.hpp"

namespace hula::server {
namespace {

// Waits until a job's event log is closed (its final event published).
void wait_finished(const Job& job) {
  while (!job.events()->next(job.events()->size(), [] {}).closed) std::this_thread::yield();
}

// checks events arrive in order as SSE frames and a waiting subscriber is woken exactly once
TEST(EventLog, BatchesInOrderAndWakesOnce) {
  EventLog log;
  int woken = 0;
  EventLog::Batch b = log.next(0, [&] { ++woken; });
  EXPECT_EQ(b.count, 0u);
  log.append("generation", Json{{"generation", 0}});
  log.append("generation", Json{{"generation", 1}});
  EXPECT_EQ(woken, 1);
  b = log.next(0, [] {});
  EXPECT_EQ(b.count, 2u);
  EXPECT_EQ(b.text, "event: generation\ndata: {\"generation\":0}\n\nevent: generation\ndata: {\"generation\":1}\n\n");
  b = log.next(2, [&] { ++woken; });
  log.close();
  EXPECT_EQ(woken, 2);
  EXPECT_TRUE(log.next(2, [] {}).closed);
}

// checks a backlog comes in whole events of at most the batch bound (one event even when it alone is
// larger), in order and none lost, and `closed` only with the batch that reaches the end of the log
TEST(EventLog, LongBacklogComesInBoundedBatches) {
  EventLog log;
  std::string expected;
  for (int g = 0; g < 1000; ++g) {
    log.append("generation", Json{{"generation", g}, {"pad", std::string(static_cast<std::size_t>(g % 7) * 20, 'x')}});
    expected += log.next(
                       static_cast<std::size_t>(g), [] {}, 1)
                    .text;
  }
  log.append("big", Json{{"pad", std::string(300, 'y')}});
  log.close();
  std::string got;
  std::size_t from = 0, batches = 0;
  for (;;) {
    const EventLog::Batch b = log.next(
        from, [] {}, 256);
    if (b.count == 0) break;
    ++batches;
    EXPECT_TRUE(b.count == 1 || b.text.size() <= 256) << b.text.size();
    EXPECT_EQ(b.closed, from + b.count == 1001) << from;
    from += b.count;
    got += b.text;
  }
  EXPECT_EQ(from, 1001U);
  EXPECT_GT(batches, 100U);
  EXPECT_EQ(got.substr(0, expected.size()), expected);
  EXPECT_EQ(got.substr(expected.size()), "event: big\ndata: {\"pad\":\"" + std::string(300, 'y') + "\"}\n\n");
}

// checks a data payload with a newline stays on one data line (JSON escapes it)
TEST(EventLog, DataIsOneLine) {
  EventLog log;
  log.append("x", Json{{"message", "a\nb"}});
  const std::string text = log.next(0, [] {}).text;
  EXPECT_EQ(text, "event: x\ndata: {\"message\":\"a\\nb\"}\n\n");
}

// checks a job's work runs on the pool, publishes events, and ends done with its result
TEST(JobPool, RunsWorkAndPublishes) {
  JobPool pool({.workers = 1, .queue_limit = 4});
  const auto job = pool.submit("test", [](JobContext& c) {
    c.publish(Json{{"generation", 0}});
    return JobOutcome{Json{{"value", 42}}, Json::object(), false};
  });
  wait_finished(*job);
  EXPECT_EQ(job->state(), JobState::Done);
  EXPECT_EQ(job->to_json()["result"]["value"], 42);
  EXPECT_EQ(job->events()->size(), 2u);
}

// checks the queue limit gives 429 and cancelling a queued job ends it cancelled without running it
TEST(JobPool, QueueLimitAndCancelQueued) {
  JobPool pool({.workers = 1, .queue_limit = 1});
  std::atomic<bool> release{false};
  std::atomic<bool> started{false};
  const auto blocker = pool.submit("block", [&](JobContext& c) {
    started = true;
    while (!release && !c.cancel.is_cancelled()) std::this_thread::yield();
    return JobOutcome{};
  });
  while (!started) std::this_thread::yield();
  bool ran = false;
  const auto queued = pool.submit("queued", [&](JobContext&) {
    ran = true;
    return JobOutcome{};
  });
  try {
    (void)pool.submit("third", [](JobContext&) { return JobOutcome{}; });
    ADD_FAILURE() << "third job accepted";
  } catch (const HttpError& e) {
    EXPECT_EQ(e.status(), 429u);
  }
  pool.cancel(*queued);
  EXPECT_EQ(queued->state(), JobState::Cancelled);
  release = true;
  pool.shutdown();
  EXPECT_FALSE(ran);
  EXPECT_EQ(blocker->state(), JobState::Done);
}

// checks a throwing job ends failed with the error's code and message
TEST(JobPool, ErrorsMakeFailedJobs) {
  JobPool pool({.workers = 1});
  const auto job =
      pool.submit("fail", [](JobContext&) -> JobOutcome { throw Error(Errc::NumericalFailure, "no finite value"); });
  wait_finished(*job);
  EXPECT_EQ(job->state(), JobState::Failed);
  EXPECT_EQ(job->to_json()["error"]["code"], "NumericalFailure");
}

}  // namespace
}  // namespace hula::server
