// SPDX-License-Identifier: MIT
// Contract tests of `hula optimise` (run as a process): the output shapes for
// one and several objectives, solution quality on ZDT1 and the sphere,
// determinism across thread counts, option errors naming the field, wall
// time and Ctrl-C ending a run with the best so far, the run log files and
// problem files.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "hula/io/atomic_file.hpp"
#include "hula/testing/process_json.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif

namespace {

using hula::testing::ProcessResult;
using hula::testing::TempDir;
using nlohmann::json;

ProcessResult hula(const std::vector<std::string>& args) {
  std::vector<std::string> all = {"optimise"};
  all.insert(all.end(), args.begin(), args.end());
  return hula::testing::run_process(HULA_CLI_PATH, all);
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// checks: NSGA-II on 10-variable ZDT1 (40 x 60, seed 1) prints a front on or above f2 = 1 - sqrt(f1)
// whose hypervolume for the default reference (1.1, 1.1) exceeds 0.6 (the true front's is 0.8690).
// (Seeds 1-10 give 0.80-0.85 here; the default 30 variables need about 150 generations for that.)
TEST(CliOptimise, Zdt1Nsga2FrontAndHypervolume) {
  const json j = hula::testing::stdout_json(hula({"--problem", "zdt1", "--dimension", "10", "--algorithm", "nsga2",
                                                  "--population", "40", "--generations", "60", "--seed", "1"}));
  ASSERT_TRUE(j.contains("front"));
  ASSERT_GT(j["front"].size(), 5u);
  for (const json& s : j["front"]) {
    EXPECT_EQ(s["variables"].size(), 10u);
    ASSERT_EQ(s["objectives"].size(), 2u);
    const double f1 = s["objectives"][0], f2 = s["objectives"][1];
    EXPECT_GE(f2, 1.0 - std::sqrt(f1) - 1e-12);  // nothing below the true front
  }
  EXPECT_GT(j["hypervolume"].get<double>(), 0.6);
  EXPECT_LE(j["hypervolume"].get<double>(), 0.8690);
  EXPECT_EQ(j["reference"], json::array({1.1, 1.1}));
  const json& report = j["report"];
  EXPECT_EQ(report["termination"], "MaxGenerations");
  EXPECT_EQ(report["generations"], 60);
  EXPECT_EQ(report["evaluations"], 40 * 61);
  EXPECT_EQ(report["failed_evaluations"], 0);
  EXPECT_EQ(report["seed"], 1);
  EXPECT_EQ(report["threads"], 1);
  EXPECT_TRUE(report["message"].is_string());
  EXPECT_TRUE(report["seconds"].is_number());
}

// checks: the real-coded GA brings the 10-D sphere below 1e-3 and prints {"best", "report"}.
TEST(CliOptimise, SphereRealGaReachesSmallObjective) {
  const json j = hula::testing::stdout_json(hula(
      {"--problem", "sphere", "--algorithm", "ga-real", "--population", "40", "--generations", "150", "--seed", "3"}));
  ASSERT_TRUE(j.contains("best"));
  EXPECT_FALSE(j.contains("front"));
  EXPECT_EQ(j["best"]["variables"].size(), 10u);
  ASSERT_EQ(j["best"]["objectives"].size(), 1u);
  EXPECT_LT(j["best"]["objectives"][0].get<double>(), 1e-3);
}

// checks: the same seed gives the same solutions and report on 1 and 2 threads (except the timing and thread count).
TEST(CliOptimise, SameSeedSameOutputOnOneAndTwoThreads) {
  for (const std::string algorithm : {"ga-real", "nsga2"}) {
    const std::string problem = algorithm == "nsga2" ? "zdt2" : "rastrigin";
    json one = hula::testing::stdout_json(hula({"--problem", problem, "--algorithm", algorithm, "--population", "20",
                                                "--generations", "10", "--seed", "7", "--threads", "1"}));
    json two = hula::testing::stdout_json(hula({"--problem", problem, "--algorithm", algorithm, "--population", "20",
                                                "--generations", "10", "--seed", "7", "--threads", "2"}));
    EXPECT_EQ(two["report"]["threads"], 2);
    for (json* j : {&one, &two}) {
      (*j)["report"].erase("seconds");
      (*j)["report"].erase("threads");
    }
    EXPECT_EQ(one.dump(), two.dump()) << algorithm;
  }
}

// checks: invalid option values exit 3 with InvalidOption naming the field and the value.
TEST(CliOptimise, BadOptionsExit3NamingTheField) {
  struct Case {
    std::vector<std::string> args;
    std::string field;
    std::string in_message;
  };
  const std::vector<Case> cases = {
      {{"--problem", "sphere", "--dimension", "2", "--algorithm", "ga-real", "--lower", "0,1", "--upper", "1,0.5"},
       "variables[1].lower",
       "variables[1].lower = 1"},
      {{"--problem", "sphere", "--dimension", "2", "--algorithm", "ga-real", "--lower", "0,1,2"}, "lower", "3 values"},
      {{"--problem", "zdt1", "--algorithm", "nsga2", "--reference", "1,1,1"}, "reference", "3 values"},
      {{"--problem", "sphere", "--algorithm", "ga-real", "--boost", "1,8"}, "boost", "ga-real"},
      {{"--problem", "sphere", "--algorithm", "ga-real", "--reference", "1"}, "reference", "several objectives"},
      {{"--problem", "sphere", "--algorithm", "ga-binary"}, "precision", "--precision"},
  };
  for (const Case& c : cases) {
    const ProcessResult r = hula(c.args);
    EXPECT_EQ(r.exit_code, 3) << c.field << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    const json e = hula::testing::stderr_error(r);
    EXPECT_EQ(e["code"], "InvalidOption") << r.err;
    EXPECT_EQ(e["where"]["field"], c.field) << r.err;
    EXPECT_NE(e["message"].get<std::string>().find(c.in_message), std::string::npos) << r.err;
  }
}

// checks: unknown problems and algorithms exit 3 (InvalidArgument naming the field); command-line
// errors (no problem, both --generations and --evaluations, a non-number, a number out of range) exit 2.
TEST(CliOptimise, UnknownNamesExit3UsageErrorsExit2) {
  const ProcessResult p = hula({"--problem", "zdt5", "--algorithm", "nsga2"});
  EXPECT_EQ(p.exit_code, 3);
  EXPECT_EQ(hula::testing::stderr_error(p)["where"]["field"], "problem");
  const ProcessResult a = hula({"--problem", "zdt1", "--algorithm", "pagmo-simplex"});
  EXPECT_EQ(a.exit_code, 3);
  EXPECT_EQ(hula::testing::stderr_error(a)["where"]["field"], "algorithm");
  EXPECT_NE(hula::testing::stderr_error(a)["message"].get<std::string>().find("pagmo-simplex"), std::string::npos);
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"--algorithm", "nsga2"},
           {"--problem", "zdt1"},
           {"--problem", "zdt1", "--problem-file", "p.json", "--algorithm", "nsga2"},
           {"--problem", "zdt1", "--algorithm", "nsga2", "--generations", "3", "--evaluations", "300"},
           {"--problem", "zdt1", "--algorithm", "nsga2", "--population", "many"},
           // Out-of-range numbers are usage errors quoting the flag (issue 10).
           {"--problem", "sphere", "--algorithm", "ga-real", "--population", "0"},
           {"--problem", "sphere", "--algorithm", "ga-real", "--crossover", "1.5"},
           {"--problem", "sphere", "--algorithm", "ga-real", "--time", "-1"}}) {
    const ProcessResult r = hula(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(hula::testing::stderr_error(r)["code"], "UsageError");
  }
}

// checks: nelder-mead on 2-variable Rosenbrock from the centre of [-5.12, 5.12]^2 reaches the known minimum (1, 1)
// and reports Converged; a budget of 10 evaluations ends it MaxEvaluations; --seed (it draws nothing) is refused
TEST(CliOptimise, NelderMeadTerminations) {
  const json j =
      hula::testing::stdout_json(hula({"--problem", "rosenbrock", "--dimension", "2", "--algorithm", "nelder-mead"}));
  EXPECT_EQ(j["report"]["termination"], "Converged") << j["report"];
  EXPECT_EQ(j["report"]["algorithm"], "nelder-mead");
  for (const double x : j["best"]["variables"]) EXPECT_NEAR(x, 1.0, 1e-6);
  const json cut = hula::testing::stdout_json(
      hula({"--problem", "rosenbrock", "--dimension", "2", "--algorithm", "nelder-mead", "--evaluations", "10"}));
  EXPECT_EQ(cut["report"]["termination"], "MaxEvaluations") << cut["report"];
  const ProcessResult seeded =
      hula({"--problem", "rosenbrock", "--dimension", "2", "--algorithm", "nelder-mead", "--seed", "3"});
  EXPECT_EQ(seeded.exit_code, 3);
  EXPECT_EQ(hula::testing::stderr_error(seeded)["where"]["field"], "seed");
}

// checks: --evaluations is the binding budget and the report says so.
TEST(CliOptimise, EvaluationBudget) {
  const json j = hula::testing::stdout_json(
      hula({"--problem", "rastrigin", "--algorithm", "ga-real", "--population", "20", "--evaluations", "200"}));
  EXPECT_EQ(j["report"]["termination"], "MaxEvaluations");
  EXPECT_LE(j["report"]["evaluations"].get<int>(), 200);
}

// checks: --time 0.2 on a run of a hundred million generations ends with WallTime and a best solution.
TEST(CliOptimise, WallTimeEndsTheRunWithTheBestSoFar) {
  const json j = hula::testing::stdout_json(hula({"--problem", "sphere", "--algorithm", "ga-real", "--population", "10",
                                                  "--generations", "100000000", "--time", "0.2"}));
  EXPECT_EQ(j["report"]["termination"], "WallTime");
  EXPECT_GE(j["report"]["seconds"].get<double>(), 0.2);
  ASSERT_EQ(j["best"]["objectives"].size(), 1u);
  EXPECT_TRUE(j["best"]["objectives"][0].is_number());
}

// Starts `hula optimise` on ZDT1 with `algorithm` for a hundred million generations with --progress, sends
// SIGINT once the first progress line is on stderr, and returns the answer on stdout (the run must exit 0).
namespace {
json interrupt_zdt1_run(const std::string& algorithm) {
  hula::testing::RunningProcess p =
      hula::testing::start_process(HULA_CLI_PATH, {"optimise", "--problem", "zdt1", "--algorithm", algorithm,
                                                   "--population", "20", "--generations", "100000000", "--progress"});
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (p.err_so_far().find("\"generation\"") == std::string::npos) {
    if (std::chrono::steady_clock::now() >= deadline) {
      ADD_FAILURE() << "no progress line on stderr";
      return json();  // the destructor kills and reaps the run
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_TRUE(p.send(SIGINT));
  const ProcessResult r = p.wait();
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? json::parse(r.out) : json();
}
}  // namespace

// checks: SIGINT sent once the run has started (a --progress line was printed) ends it with
// exit 0, termination Cancelled and the best so far on stdout.
TEST(CliOptimise, SigintCancelsWithTheBestSoFar) {
  const json j = interrupt_zdt1_run("nsga2");
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j["report"]["termination"], "Cancelled");
  EXPECT_FALSE(j["front"].empty());
  // Early fronts of ZDT1 may lie beyond the reference (hypervolume 0), but it is always reported.
  EXPECT_GE(j["hypervolume"].get<double>(), 0.0);
}

// checks: pagmo's algorithms stop early too (the adapter looks at the token and the clock before each
// evaluation): --time 0.2 on a hundred million generations of pagmo-pso (no tolerance of its own ends it)
// ends WallTime with a best whose
// objective is the sphere's value at its variables; SIGINT once a progress line is out ends a pagmo-nsga2
// run on ZDT1 Cancelled with exit 0 and a mutually non-dominated front.
TEST(CliOptimise, PagmoRunsStopOnTimeAndSigint) {
  const json j =
      hula::testing::stdout_json(hula({"--problem", "sphere", "--dimension", "3", "--algorithm", "pagmo-pso",
                                       "--population", "10", "--generations", "100000000", "--time", "0.2"}));
  EXPECT_EQ(j["report"]["termination"], "WallTime") << j["report"];
  EXPECT_GE(j["report"]["seconds"].get<double>(), 0.2);
  EXPECT_NE(j["report"]["message"].get<std::string>().find("generations of pagmo pso"), std::string::npos);
  double sum = 0.0;
  for (const double x : j["best"]["variables"]) sum += x * x;
  EXPECT_EQ(j["best"]["objectives"][0].get<double>(), sum);

  const json c = interrupt_zdt1_run("pagmo-nsga2");
  ASSERT_TRUE(c.is_object());
  EXPECT_EQ(c["report"]["termination"], "Cancelled");
  ASSERT_FALSE(c["front"].empty());
  for (const json& a : c["front"])
    for (const json& b : c["front"]) {
      const double a0 = a["objectives"][0], a1 = a["objectives"][1], b0 = b["objectives"][0], b1 = b["objectives"][1];
      EXPECT_FALSE(b0 <= a0 && b1 <= a1 && (b0 < a0 || b1 < a1)) << a << " is dominated by " << b;
    }
}

// checks: --log writes the run log as CSV (header, one row per individual and generation) or
// JSON (one entry per generation), atomically.
TEST(CliOptimise, LogFilesParse) {
  TempDir dir;
  const auto csv = dir / "run.csv";
  (void)hula::testing::stdout_json(hula({"--problem", "sphere", "--dimension", "3", "--algorithm", "ga-real",
                                         "--population", "4", "--generations", "2", "--log", csv.string()}));
  std::istringstream lines(slurp(csv));
  std::string header, row;
  std::getline(lines, header);
  EXPECT_EQ(header.rfind("generation,evaluations,individual,", 0), 0u) << header;
  std::size_t rows = 0;
  while (std::getline(lines, row)) ++rows;
  EXPECT_EQ(rows, 4u * 3u);

  const auto js = dir / "run.json";
  (void)hula::testing::stdout_json(hula(
      {"--problem", "zdt1", "--algorithm", "nsga2", "--population", "8", "--generations", "2", "--log", js.string()}));
  const json log = json::parse(slurp(js));
  ASSERT_EQ(log["generations"].size(), 3u);
  EXPECT_EQ(log["generations"][2]["individuals"].size(), 8u);
  EXPECT_EQ(dir.names(), (std::vector<std::string>{"run.csv", "run.json"}));
}

// checks: a problem file with a constraint is solved (the constrained optimum of
// x^2 + y^2 subject to x + y >= 1 is (0.5, 0.5) with f = 0.5), and its reference is used.
TEST(CliOptimise, ProblemFile) {
  TempDir dir;
  hula::io::write_file_atomically(dir / "p.json", R"j({
    "name": "circle-cut",
    "variables": [{"name": "x", "lower": -2, "upper": 2}, {"name": "y", "lower": -2, "upper": 2}],
    "objectives": ["x^2 + y^2"],
    "constraints": [{"expression": "1 - x - y", "type": "inequality"}]
  })j");
  const json j = hula::testing::stdout_json(hula({"--problem-file", (dir / "p.json").string(), "--algorithm", "ga-real",
                                                  "--population", "40", "--generations", "100", "--seed", "2"}));
  EXPECT_NEAR(j["best"]["objectives"][0].get<double>(), 0.5, 1e-2);
  EXPECT_LE(j["best"]["violation"].get<double>(), 0.0);
  EXPECT_EQ(j["report"]["problem"], "circle-cut");

  hula::io::write_file_atomically(dir / "mo.json", R"j({
    "variables": [{"name": "x", "lower": 0, "upper": 1}],
    "objectives": ["x", "1 - sqrt(x)"],
    "reference": [2, 2]
})j");
  const json m = hula::testing::stdout_json(hula({"--problem-file", (dir / "mo.json").string(), "--algorithm", "nsga2",
                                                  "--population", "20", "--generations", "20"}));
  EXPECT_EQ(m["reference"], json::array({2, 2}));
  EXPECT_GT(m["hypervolume"].get<double>(), 3.0);
}

// checks: an expression error names the member and the parser's line/column; a missing file is IoError.
TEST(CliOptimise, ProblemFileErrors) {
  TempDir dir;
  hula::io::write_file_atomically(dir / "bad.json", R"j({
    "variables": [{"name": "x", "lower": 0, "upper": 1}],
    "objectives": ["x", "sin(x"]
  })j");
  const ProcessResult r = hula({"--problem-file", (dir / "bad.json").string(), "--algorithm", "nsga2"});
  EXPECT_EQ(r.exit_code, 3);
  const json e = hula::testing::stderr_error(r);
  EXPECT_EQ(e["code"], "ParseError");
  EXPECT_EQ(e["where"]["field"], "objectives");
  EXPECT_EQ(e["where"]["index"], 1);
  EXPECT_EQ(e["where"]["line"], 1);
  EXPECT_TRUE(e["where"]["column"].is_number());
  EXPECT_EQ(e["message"].get<std::string>().rfind("objectives[1]: ", 0), 0u) << e["message"];

  const ProcessResult m = hula({"--problem-file", (dir / "none.json").string(), "--algorithm", "nsga2"});
  EXPECT_EQ(m.exit_code, 3);
  EXPECT_EQ(hula::testing::stderr_error(m)["code"], "IoError");
}

}  // namespace
