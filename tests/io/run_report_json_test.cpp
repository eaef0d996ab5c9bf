// SPDX-License-Identifier: MIT
// The run report codec: written once for every report (issue 10), the member
// names and order of the contract (docs/cli.md, server/openapi.json), read
// back equal, and bad reports refused naming the member.
#include "hula/io/run_report_json.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace hula::io
