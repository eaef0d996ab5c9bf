// SPDX-License-Identifier: MIT
// parallel_for covers every index once and reports the lowest failing index.
#include "hula/core/parallel.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula {
namespace {

// checks: every index runs exactly once, for 1, 2 and default threads.
TEST(ParallelFor, VisitsEveryIndexOnce) {
  for (std::size_t threads : {1u, 2u, 0u}) {
    std::vector<std::atomic<int>> hits(1000);
    parallel_for(0, hits.size(), [&](std::size_t i) { hits[i]++; }, {.threads = threads, .grain = 7});
    for (auto& h : hits) EXPECT_EQ(h.load(), 1);
  }
}

// checks: when several iterations throw, the lowest index's error is rethrown on any thread count.
TEST(ParallelFor, LowestIndexErrorWins) {
  for (std::size_t threads : {1u, 2u, 0u}) {
    try {
      parallel_for(0, 500,
                   [](std::size_t i) {
                     if (i % 97 == 13) throw std::runtime_error("failed at " + std::to_string(i));
                   },
                   {.threads = threads});
      FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "failed at 13");
    }
  }
  HULA_EXPECT_ERROR(parallel_for(0, 1, [](std::size_t) {}, {.grain = 0}), Errc::InvalidOption, "grain");
}

}  // namespace
}  // namespace hula
