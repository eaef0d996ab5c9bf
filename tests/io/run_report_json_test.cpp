// SPDX-License-Identifier: MIT
// The run report codec: written once for every report (issue 10), the member
// names and order of the contract (docs/cli.md, server/openapi.json), read
// back equal, and bad reports refused naming the member.
#include "hula/io/run_report_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "hula/core/error.hpp"

namespace hula::io {
namespace {

optim::RunReport sample() {
  optim::RunReport r;
  r.termination = optim::Termination::Stagnation;
  r.message = "no improvement for 20 generations";
  r.generations = 57;
  r.evaluations = 5800;
  r.failed_evaluations = 3;
  r.seconds = 0.125;
  return r;
}

// Checks the members and their order against the contract, identity members only when set.
TEST(RunReportJson, MembersInContractOrder) {
  const Json bare = run_report_to_json(sample());
  std::vector<std::string> names;
  for (const auto& [k, v] : bare.items()) names.push_back(k);
  EXPECT_EQ(names, (std::vector<std::string>{"termination", "message", "generations", "evaluations",
                                             "failed_evaluations", "seconds"}));
  EXPECT_EQ(bare["termination"], "Stagnation");
  const Json full = run_report_to_json(sample(), {.seed = 7, .threads = 2, .algorithm = "nsga2", .problem = "zdt1"});
  names.clear();
  for (const auto& [k, v] : full.items()) names.push_back(k);
  EXPECT_EQ(names,
            (std::vector<std::string>{"termination", "message", "generations", "evaluations", "failed_evaluations",
                                      "seconds", "seed", "threads", "algorithm", "problem"}));
  EXPECT_EQ(full["seed"], 7);
  EXPECT_EQ(full["problem"], "zdt1");
}

// Checks read-after-write gives the report back, for every termination.
TEST(RunReportJson, ReadAfterWrite) {
  for (const optim::Termination t :
       {optim::Termination::MaxGenerations, optim::Termination::MaxEvaluations, optim::Termination::TargetReached,
        optim::Termination::Stagnation, optim::Termination::WallTime, optim::Termination::Cancelled,
        optim::Termination::Converged}) {
    optim::RunReport r = sample();
    r.termination = t;
    const optim::RunReport back = run_report_from_json(Json::parse(run_report_to_json(r, {.seed = 1}).dump()));
    EXPECT_EQ(back.termination, t);
    EXPECT_EQ(back.message, r.message);
    EXPECT_EQ(back.generations, r.generations);
    EXPECT_EQ(back.evaluations, r.evaluations);
    EXPECT_EQ(back.failed_evaluations, r.failed_evaluations);
    EXPECT_EQ(back.seconds, r.seconds);
  }
}

// Checks an unknown termination and a missing member are ParseErrors naming the member.
TEST(RunReportJson, BadReportNamesTheMember) {
  Json j = run_report_to_json(sample());
  j["termination"] = "Bored";
  try {
    (void)run_report_from_json(j);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Errc::ParseError);
    EXPECT_NE(e.message().find("termination"), std::string::npos);
  }
  j = run_report_to_json(sample());
  j.erase("evaluations");
  try {
    (void)run_report_from_json(j);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Errc::ParseError);
    EXPECT_NE(e.message().find("evaluations"), std::string::npos);
  }
}

// A two-generation log with a NaN objective (a failed individual), an infinite violation and two variables.
optim::RunLog sample_log() {
  optim::RunLog log;
  for (std::size_t k = 0; k < 2; ++k) {
    optim::GenerationLog g;
    g.generation = k;
    g.evaluations = 3 * (k + 1);
    g.dimension = 2;
    g.objectives = 1;
    g.variables = {0.1 * static_cast<double>(k), 1.0 / 3.0, -2.5, 7.0, 1e-17, -0.0};
    g.objective_values = {0.5, std::numeric_limits<double>::quiet_NaN(), 2.0 + static_cast<double>(k)};
    g.violation = {0.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()};
    g.fitness = {0.75, 0.0, 0.125};
    g.failed = {0, 1, 0};
    log.append(g);
  }
  return log;
}

// Checks run_log_to_json writes what optim::RunLog::write_json writes (the `--log` file, its own writer),
// and run_log_from_json reads it back to the same log (NaN for null, so the infinite violation comes back
// NaN) and the same JSON.
TEST(RunReportJson, RunLogReadAfterWrite) {
  const optim::RunLog log = sample_log();
  std::ostringstream file;
  log.write_json(file);
  const Json written = run_log_to_json(log);
  EXPECT_EQ(written, Json::parse(file.str()));
  const optim::RunLog back = run_log_from_json(Json::parse(written.dump()));
  EXPECT_EQ(run_log_to_json(back), written);
  optim::RunLog expected = sample_log();
  ASSERT_EQ(back.generations().size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    optim::GenerationLog g = expected.generations()[k];
    g.violation[2] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(back.generations()[k], g) << "generation " << k;
  }
}

// Checks bad logs are ParseErrors naming the member: a variables count that differs from individual 0's,
// a failed flag that is not a boolean, an unknown member, a log that is not an object.
TEST(RunReportJson, BadRunLogNamesTheMember) {
  const auto refusal = [](const Json& log) {
    try {
      (void)run_log_from_json(log);
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), Errc::ParseError);
      return e.message();
    }
    return std::string("accepted");
  };
  Json j = run_log_to_json(sample_log());
  j["generations"][1]["individuals"][2]["variables"].push_back(1.0);
  EXPECT_NE(refusal(j).find("log.generations[1].individuals[2].variables has 3 values where individual 0 has 2"),
            std::string::npos)
      << refusal(j);
  j = run_log_to_json(sample_log());
  j["generations"][0]["individuals"][1]["failed"] = 1;
  EXPECT_NE(refusal(j).find("log.generations[0].individuals[1].failed"), std::string::npos) << refusal(j);
  j = run_log_to_json(sample_log());
  j["generations"][0]["best"] = 1;
  EXPECT_NE(refusal(j).find("best"), std::string::npos) << refusal(j);
  EXPECT_NE(refusal(Json::array({1})).find("log"), std::string::npos);
}

}  // namespace
}  // namespace hula::io
