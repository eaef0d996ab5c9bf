// SPDX-License-Identifier: MIT
// The fairing preview codec (POST .../fair-preview): the request's members and
// defaults, its errors naming the member, and the ghost's members in the order
// of the contract (docs/server.md, server/openapi.json).
#include "hula/io/fair_preview_json.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hula/testing/expect_error.hpp"

namespace hula::io {
namespace {

// checks the defaults of studies::AssistantOptions are kept for the members left out, and no analysis
TEST(FairPreviewJson, RequestDefaults) {
  const FairPreviewRequest r = fair_preview_request_from_json(Json::parse(R"({"tolerance": 0.5})"));
  EXPECT_EQ(r.options.tolerance, 0.5);
  EXPECT_EQ(r.options.method, studies::AssistantMethod::MinimalVariation);
  EXPECT_EQ(r.options.time_budget_seconds, 0.1);
  EXPECT_EQ(r.options.hold, studies::AssistantHold::Free);
  EXPECT_FALSE(r.analysis.has_value());
}

// checks every member is read: the knot method by its name, the budget, and the analysis kept as given
TEST(FairPreviewJson, RequestEveryMember) {
  const FairPreviewRequest r = fair_preview_request_from_json(
      Json::parse(R"({"tolerance": 0.25, "method": "knots", "budget": 2, "hold": "tangents",
                      "analysis": {"samples": 5, "by": "x"}})"));
  EXPECT_EQ(r.options.tolerance, 0.25);
  EXPECT_EQ(r.options.hold, studies::AssistantHold::Tangents);
  EXPECT_EQ(r.options.method, studies::AssistantMethod::Knots);
  EXPECT_EQ(r.options.time_budget_seconds, 2.0);
  ASSERT_TRUE(r.analysis.has_value());
  EXPECT_EQ(*r.analysis, Json::parse(R"({"samples": 5, "by": "x"})"));
}

// checks the "curve" member (an edit in flight) is read as a curve: written back it is the curve sent; absent, none
TEST(FairPreviewJson, RequestCurveInFlight) {
  curve::BezierData bezier;
  bezier.control_points = {{0, 0, 0}, {1, 2, 0}, {3, 0, 1}};
  const Json sent = curve_to_json(curve::Curve::bezier(bezier));
  Json body = Json::parse(R"({"tolerance": 0.5})");
  EXPECT_FALSE(fair_preview_request_from_json(body).curve.has_value());
  body["curve"] = sent;
  const FairPreviewRequest r = fair_preview_request_from_json(body);
  ASSERT_TRUE(r.curve.has_value());
  EXPECT_EQ(curve_to_json(*r.curve), sent);
  body["curve"] = Json::parse(R"({"kind": "spiral"})");
  EXPECT_THROW((void)fair_preview_request_from_json(body), Error);
}

// checks bad requests are refused naming the member: unknown, missing, mistyped, out of range, unknown method
TEST(FairPreviewJson, RequestErrorsNameTheMember) {
  HULA_EXPECT_ERROR(fair_preview_request_from_json(Json::parse(R"({"tolerance": 1, "colour": 2})")), Errc::ParseError,
                    "colour");
  HULA_EXPECT_ERROR(fair_preview_request_from_json(Json::parse(R"({})")), Errc::ParseError, "tolerance");
  HULA_EXPECT_ERROR(fair_preview_request_from_json(Json::parse(R"({"tolerance": "1"})")), Errc::ParseError,
                    "tolerance");
  HULA_EXPECT_ERROR(fair_preview_request_from_json(Json::parse(R"({"tolerance": 0})")), Errc::InvalidOption,
                    "tolerance");
  HULA_EXPECT_ERROR(fair_preview_request_from_json(Json::parse(R"({"tolerance": 1, "budget": 61})")),
                    Errc::InvalidOption, "budget");
  HULA_EXPECT_ERROR(fair_preview_request_from_json(Json::parse(R"({"tolerance": 1, "method": "smooth"})")),
                    Errc::InvalidOption, "smooth");
  HULA_EXPECT_ERROR(fair_preview_request_from_json(Json::parse(R"({"tolerance": 1, "hold": "ends"})")),
                    Errc::InvalidOption, "hold");
  HULA_EXPECT_ERROR(fair_preview_request_from_json(Json::parse(R"({"tolerance": 1, "hold": true})")), Errc::ParseError,
                    "hold");
}

// checks the ghost's members and their order against the contract, and each value against the result given
TEST(FairPreviewJson, GhostMembersInContractOrder) {
  curve::BezierData bezier;
  bezier.control_points = {{0, 0, 0}, {1, 2, 0}, {3, 0, 1}};
  studies::AssistantResult r{.curve = curve::Curve::bezier(bezier)};
  r.energy_before = 4.5;
  r.energy_after = 1.25;
  r.data_points = {{0, 0, 0}, {1, 2, 0}, {3, 0, 1}};
  r.faired_points = {{0, 0, 0}, {1, 1.75, 0}, {3, 0, 1}};
  r.max_deviation = 0.25;
  r.iterations = 7;
  r.stopped = true;
  r.seconds = 0.0625;
  studies::AssistantOptions options;
  options.tolerance = 0.5;
  options.method = studies::AssistantMethod::Knots;
  options.hold = studies::AssistantHold::Points;
  const Json j = fair_preview_to_json(r, options, 12);
  std::vector<std::string> names;
  for (const auto& [k, v] : j.items()) names.push_back(k);
  EXPECT_EQ(names, (std::vector<std::string>{"revision", "method", "tolerance", "curve", "energy_before",
                                             "energy_after", "max_deviation", "data_points", "faired_points",
                                             "iterations", "stopped", "seconds", "hold"}));
  EXPECT_EQ(j["hold"], "points");
  EXPECT_EQ(j["revision"], 12);
  EXPECT_EQ(j["method"], "knots");
  EXPECT_EQ(j["tolerance"], 0.5);
  EXPECT_EQ(j["curve"]["kind"], "bezier");
  EXPECT_EQ(j["curve"]["control_points"][1], Json::parse("[1, 2, 0]"));
  EXPECT_EQ(j["energy_before"], 4.5);
  EXPECT_EQ(j["energy_after"], 1.25);
  EXPECT_EQ(j["max_deviation"], 0.25);
  EXPECT_EQ(j["data_points"], Json::parse("[[0, 0, 0], [1, 2, 0], [3, 0, 1]]"));
  EXPECT_EQ(j["faired_points"][1], Json::parse("[1, 1.75, 0]"));
  EXPECT_EQ(j["iterations"], 7);
  EXPECT_EQ(j["stopped"], true);
  EXPECT_EQ(j["seconds"], 0.0625);
}

}  // namespace
}  // namespace hula::io
