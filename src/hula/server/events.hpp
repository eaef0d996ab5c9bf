// SPDX-License-Identifier: MIT
// An append-only log of Server-Sent Events shared by any number of
// subscribers (a job's generations, a document's change sets). Producers
// append on their own thread; a subscriber asks for the events after the
// last one it sent and, when there are none yet, leaves a wake-up callback
// that the next append (or close) calls once. No thread waits per
// subscriber, so hundreds of streams cost only their sockets.
#pragma once

#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "hula/server/http.hpp"

namespace hula::server {

class EventLog {
 public:
  /// Appends "event: NAME\ndata: JSON\n\n" and wakes the waiting subscribers.
  void append(std::string_view name, const Json& data);
  /// Marks the log complete (no more events) and wakes the waiting subscribers.
  void close();

  /// Events [from, size) concatenated, how many they are, and whether the log is closed.
  struct Batch {
    std::string text{};
    std::size_t count = 0;
    bool closed = false;
  };

  /// The events after `from`, whole events up to about `max_bytes` (at least one), so that a
  /// stream's write timeout measures a stalled client, not the time to drain a long backlog;
  /// `closed` only when the batch reaches the end of a closed log. When there are none and the
  /// log is open, `wake` is stored and called once (on the appending thread) by the next append
  /// or close.
  [[nodiscard]] Batch next(std::size_t from, std::function<void()> wake, std::size_t max_bytes = kBatchBytes);

  /// The default bound of a batch's text.
  static constexpr std::size_t kBatchBytes = std::size_t{64} * 1024;

  /// Number of events so far.
  [[nodiscard]] std::size_t size() const;

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> events_;
  std::vector<std::function<void()>> waiting_;
  bool closed_ = false;
  void wake_all(std::unique_lock<std::mutex>& lock);
};

}  // namespace hula::server
