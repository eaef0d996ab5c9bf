// SPDX-License-Identifier: MIT
// Contract tests of `hula log-aesthetic` run as a process (issue 26): the JSON shape, κ and dκ/ds at --at
// against the closed forms κ = (ρ0^α + αλs)^(−1/α), dκ/ds = −λ κ^(1+α) to 1e-12 (the analysis of the exact
// curve, not of a stand-in), the curve file written by its law (kind natural) and read back exact, and
// exit codes 2/3 with the error naming the input.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hula/curve/curve.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/testing/process_json.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif

namespace hula::intrinsic {
namespace {

using nlohmann::json;
using testing::ProcessResult;

ProcessResult hula(const std::vector<std::string>& args) { return testing::run_process(HULA_CLI_PATH, args); }

// checks: α = 1, ρ0 = 1.5, λ = 0.4 (κ = 1/(1.5 + 0.4 s), the example): κ and κ' at --at to 1e-12
// relative, the printed law, the documented keys; -o writes the natural curve whose κ' is exact too.
TEST(LogAestheticCli, ExactCurvatureAndFile) {
  testing::TempDir dir;
  const std::string out = (dir.path() / "la.json").string();
  const ProcessResult r = hula({"log-aesthetic", "--alpha", "1", "--rho0", "1.5", "--lambda", "0.4", "--length", "6",
                                "--at", "0,1.7,6", "-o", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  for (const char* key : {"alpha", "rho0", "lambda", "length", "max_length", "curvature", "points", "output"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_TRUE(j["max_length"].is_null());  // αλ > 0: the radius grows without end
  ASSERT_EQ(j["points"].size(), 3U);
  for (const json& p : j["points"]) {
    const double s = p["s"].get<double>(), k = 1.0 / (1.5 + 0.4 * s);
    EXPECT_NEAR(p["kappa"].get<double>(), k, 1e-12 * k) << s;
    EXPECT_NEAR(p["kappa_prime"].get<double>(), -0.4 * k * k, 1e-12 * 0.4 * k * k) << s;
  }
  EXPECT_EQ(j["output"]["kind"], "natural");
  const curve::Curve c = io::read_curve_file(out);
  ASSERT_EQ(c.kind(), curve::Kind::Natural);
  EXPECT_EQ(std::get<curve::NaturalData>(c.data()).curvature, j["curvature"].get<std::string>());
  EXPECT_EQ(c.length(), 6.0);
}

// checks: a length past the family's end (α = −1, λ > 0: κ reaches 0 at s = ρ0^(−1)/λ... the radius is infinite)
// and a bad ρ0 exit 3 naming the field; a missing required option exits 2.
TEST(LogAestheticCli, BadParameters) {
  const ProcessResult r = hula({"log-aesthetic", "--alpha", "-1", "--rho0", "2", "--lambda", "0.3", "--length", "5"});
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_EQ(testing::stderr_error(r)["where"]["field"], "length");
  EXPECT_EQ(hula({"log-aesthetic", "--alpha", "1", "--rho0", "0", "--lambda", "0.3", "--length", "5"}).exit_code, 2);
  EXPECT_EQ(hula({"log-aesthetic", "--alpha", "1", "--rho0", "1", "--length", "5"}).exit_code, 2);
}

}  // namespace
}  // namespace hula::intrinsic
