// SPDX-License-Identifier: MIT
// Issue 24, items 6 and 16: the report an MPI rank sends rank 0 at the end of a
// run states counts (solutions, migrations, string lengths) before its arrays.
// Rank 0 sizes its receive buffer by the message, and every count read from it
// is bounded by the bytes that remain before anything is allocated: a short or
// hostile report is refused naming the count and the byte, never allocated.
// (Built only with HULA_MPI: the reader lives in hula::optim_mpi.)
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "hula/optim/islands_mpi.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::optim {
namespace {

IslandReport sample_report() {
  IslandReport r;
  r.island = 3;
  r.seed = 0x1234567890abcdefULL;
  r.best = {{0.25, -1.5}, {7.0}, 0.0};
  r.population = {{{1.0, 2.0}, {3.0, 4.0}, 0.5}, {{-1.0, 0.0}, {2.0, 1.0}, 0.0}};
  r.archive = {{{9.0, 8.0}, {1.0, 1.0}, 0.0}};
  r.report.termination = Termination::MaxGenerations;
  r.report.message = "30 generations run";
  r.report.generations = 30;
  r.report.evaluations = 620;
  r.report.failed_evaluations = 2;
  r.report.seconds = 0.125;
  r.sent = 11;
  r.received = 12;
  r.accepted = 5;
  r.migrations = {{10, 2, 3, 4, 1}, {20, 2, 3, 4, 2}};
  return r;
}

void expect_same_solution(const Solution& a, const Solution& b) {
  EXPECT_EQ(a.variables, b.variables);
  EXPECT_EQ(a.objectives, b.objectives);
  EXPECT_EQ(a.violation, b.violation);
}

// Where the population count sits: kind (1), island (8), seed (8), best (two counts, 3 values, violation).
constexpr std::size_t kPopulationCount = 1 + 8 + 8 + (8 + 2 * 8) + (8 + 1 * 8) + 8;

void put_u64(std::vector<char>& bytes, std::size_t at, std::uint64_t v) { std::memcpy(bytes.data() + at, &v, 8); }

// checks a report read back equals the one written, member for member (the hand-built values above)
TEST(Issue24IslandReport, ReadsBackWhatWasWritten) {
  const IslandReport r = sample_report();
  const IslandReport back = read_island_report(write_island_report(r));
  EXPECT_EQ(back.island, 3U);
  EXPECT_EQ(back.seed, 0x1234567890abcdefULL);
  expect_same_solution(back.best, r.best);
  ASSERT_EQ(back.population.size(), 2U);
  for (std::size_t i = 0; i < 2; ++i) expect_same_solution(back.population[i], r.population[i]);
  ASSERT_EQ(back.archive.size(), 1U);
  expect_same_solution(back.archive[0], r.archive[0]);
  EXPECT_EQ(back.report.message, "30 generations run");
  EXPECT_EQ(back.report.generations, 30U);
  EXPECT_EQ(back.report.evaluations, 620U);
  EXPECT_EQ(back.report.failed_evaluations, 2U);
  EXPECT_EQ(back.report.seconds, 0.125);
  EXPECT_EQ(back.sent, 11U);
  EXPECT_EQ(back.received, 12U);
  EXPECT_EQ(back.accepted, 5U);
  ASSERT_EQ(back.migrations.size(), 2U);
  EXPECT_EQ(back.migrations[1].generation, 20U);
  EXPECT_EQ(back.migrations[1].accepted, 2U);
  // The layout the offsets below rely on: the population count where it is computed to be.
  std::uint64_t count = 0;
  const auto bytes = write_island_report(r);
  std::memcpy(&count, bytes.data() + kPopulationCount, 8);
  EXPECT_EQ(count, 2U);
}

// checks every proper prefix of a report is refused as a truncated report (no crash, no partial result)
TEST(Issue24IslandReport, EveryTruncationIsRefused) {
  const auto bytes = write_island_report(sample_report());
  for (std::size_t n = 1; n < bytes.size(); ++n) {
    const std::vector<char> part(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(n));
    HULA_EXPECT_ERROR(read_island_report(part), Errc::IoError, "truncated island report");
  }
}

// checks a hostile population count (150,000,000 and 2^64 - 1 solutions in a message of a few hundred bytes),
// migration count and string length are refused naming the count and the bytes that remain, before any
// allocation (a 150,000,000-solution vector would take 10 GB)
TEST(Issue24IslandReport, HostileCountsAreRefusedBeforeAllocating) {
  const auto good = write_island_report(sample_report());
  for (const std::uint64_t n : {std::uint64_t{150'000'000}, std::numeric_limits<std::uint64_t>::max()}) {
    auto bytes = good;
    put_u64(bytes, kPopulationCount, n);
    HULA_EXPECT_ERROR(read_island_report(bytes), Errc::IoError, "states " + std::to_string(n) + " elements");
    HULA_EXPECT_ERROR(read_island_report(bytes), Errc::IoError, "bytes remain");
  }
  // The migration count is the last 8 bytes before the two events (5 numbers each).
  auto bytes = good;
  put_u64(bytes, bytes.size() - 2 * 5 * 8 - 8, 150'000'000);
  HULA_EXPECT_ERROR(read_island_report(bytes), Errc::IoError, "states 150000000 elements of at least 40 bytes");
  // The best solution's variable count, the first count of the report.
  bytes = good;
  put_u64(bytes, 1 + 8 + 8, 0xFFFFFFFFULL);
  HULA_EXPECT_ERROR(read_island_report(bytes), Errc::IoError, "states 4294967295 elements of at least 8 bytes");
  // The message's length: after the archive, the termination byte.
  const std::size_t archive_count = kPopulationCount + 8 + 2 * (8 + 2 * 8 + 8 + 2 * 8 + 8);
  const std::size_t message_length = archive_count + 8 + (8 + 2 * 8 + 8 + 2 * 8 + 8) + 1;
  bytes = good;
  std::uint64_t length = 0;
  std::memcpy(&length, bytes.data() + message_length, 8);
  ASSERT_EQ(length, std::string("30 generations run").size());
  put_u64(bytes, message_length, std::numeric_limits<std::uint64_t>::max());
  HULA_EXPECT_ERROR(read_island_report(bytes), Errc::IoError, "elements of at least 1 bytes");
}

}  // namespace
}  // namespace hula::optim
