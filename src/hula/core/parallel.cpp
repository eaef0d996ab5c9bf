// SPDX-License-Identifier: MIT
#include "hula/core/parallel.hpp"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <exception>
#include <limits>
#include <mutex>

#include "hula/core/error.hpp"

namespace hula {

void parallel_for(std::size_t begin, std::size_t end, const std::function<void(std::size_t)>& body,
                  const ParallelOptions& options) {
  if (options.grain == 0) throw Error(Errc::InvalidOption, "parallel grain = 0 must be >= 1", {.field = "grain"});
  if (begin >= end) return;

  std::mutex mutex;
  std::size_t first_failed = std::numeric_limits<std::size_t>::max();
  std::exception_ptr first_error;
  auto run_one = [&](std::size_t i) {
    try {
      body(i);
    } catch (...) {
      const std::scoped_lock lock(mutex);
      if (i < first_failed) {
        first_failed = i;
        first_error = std::current_exception();
      }
    }
  };

  if (options.threads == 1) {
    for (std::size_t i = begin; i < end; ++i) run_one(i);
  } else {
    auto loop = [&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, options.grain),
                        [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) run_one(i);
                        });
    };
    if (options.threads == 0) {
      loop();
    } else {
      tbb::task_arena arena(static_cast<int>(options.threads));
      arena.execute(loop);
    }
  }
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace hula
