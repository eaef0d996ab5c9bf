// SPDX-License-Identifier: MIT
// The event log behind every SSE stream (events.hpp).
#include "hula/server/events.hpp"

namespace hula::server {

void EventLog::wake_all(std::unique_lock<std::mutex>& lock) {
  std::vector<std::function<void()>> waiting;
  waiting.swap(waiting_);
  lock.unlock();  // a callback may call next() at once
  for (auto& w : waiting) w();
}

void EventLog::append(std::string_view name, const Json& data) {
  std::string text = "event: ";
  text += name;
  text += "\ndata: ";
  text += data.dump(-1, ' ', false, Json::error_handler_t::replace);  // one line: dump() escapes newlines
  text += "\n\n";
  std::unique_lock lock(mutex_);
  if (closed_) return;
  events_.push_back(std::move(text));
  wake_all(lock);
}

void EventLog::close() {
  std::unique_lock lock(mutex_);
  closed_ = true;
  wake_all(lock);
}

EventLog::Batch EventLog::next(std::size_t from, std::function<void()> wake, std::size_t max_bytes) {
  std::lock_guard lock(mutex_);
  Batch b;
  std::size_t i = from;
  for (; i < events_.size() && (i == from || b.text.size() + events_[i].size() <= max_bytes); ++i) b.text += events_[i];
  b.count = i > from ? i - from : 0;
  b.closed = closed_ && i >= events_.size();
  if (b.count == 0 && !closed_) waiting_.push_back(std::move(wake));
  return b;
}

std::size_t EventLog::size() const {
  std::lock_guard lock(mutex_);
  return events_.size();
}

}  // namespace hula::server
