// SPDX-License-Identifier: MIT
// Law values and derivatives at parameters (io/law_values.hpp): one compiled
// tape for the law and its derivatives, evaluated point by point so that the
// first undefined point is named.
#include "hula/io/law_values.hpp"

#include <cmath>
#include <limits>

#include "hula/core/error.hpp"
#include "hula/io/json_read.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/singularities.hpp"
#include "hula/law/tape.hpp"

namespace hula::io {

LawValues law_derivatives(const law::Law& l, const std::string& parameter, std::span<const double> ts, int order) {
  const std::vector<law::Law> laws = law::derivatives(l, parameter, order);
  const std::string in[1] = {parameter};
  const law::Tape tape = law::Tape::compile(laws, in);
  LawValues out;
  law::Workspace w = tape.make_workspace();
  for (std::size_t i = 0; i < ts.size(); ++i) {
    std::vector<double> v(tape.output_count());
    (void)tape.evaluate(ts.subspan(i, 1), v, w);
    const std::string at = parameter + "[" + std::to_string(i) + "] = " + format_number(ts[i]);
    // The kink check comes first: past a kink the derivatives are not numbers, whatever the tape says.
    std::optional<law::NonSmoothPoint> kink = law::nonsmooth_at(l, parameter, ts[i], order);
    const std::size_t valid = static_cast<std::size_t>(kink ? kink->order : order + 1) * laws.front().dimension();
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (k >= valid) {
        v[k] = std::numeric_limits<double>::quiet_NaN();
        continue;
      }
      if (std::isfinite(v[k])) continue;
      // Name the innermost failing subexpression of the law or of the derivative that failed.
      const law::Law& failed = laws[k / static_cast<std::size_t>(laws.front().dimension())];
      const auto cause = law::explain_non_finite(failed, parameter, ts[i]);
      const std::string why = cause ? " (" + cause->expression + ": " + cause->reason + ")" : "";
      if (cause && cause->overflow)
        throw Error(Errc::NumericalFailure,
                    at + ": the law" + (failed == l ? std::string() : " derivative") + " overflows there" + why,
                    ErrorWhere{.field = parameter, .index = i});
      throw Error(Errc::OutOfDomain,
                  at +
                      (order == 0 ? std::string(": the law is undefined there")
                                  : ": the law or one of its first " + std::to_string(order) +
                                        " derivatives is undefined there") +
                      why,
                  ErrorWhere{.field = parameter, .index = i});
    }
    out.values.push_back(std::move(v));
    out.kinks.push_back(std::move(kink));
  }
  return out;
}

Json law_results_to_json(std::span<const double> ts, const LawValues& values, int dimension, int order) {
  Json results = Json::array();
  const auto d = static_cast<std::size_t>(dimension);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    Json ders = Json::array();
    for (std::size_t k = 0; k <= static_cast<std::size_t>(order); ++k) {
      Json v = Json::array();
      for (std::size_t c = 0; c < d; ++c) {
        const double x = values.values[i][k * d + c];
        v.push_back(std::isnan(x) ? Json(nullptr) : Json(x));
      }
      ders.push_back(std::move(v));
    }
    Json r = Json::object();
    r["t"] = ts[i];
    r["derivatives"] = std::move(ders);
    if (const auto& kink = values.kinks[i]) {
      Json u = Json::object();
      u["order"] = kink->order;
      u["kind"] = law::singularity_kind_name(kink->kind);
      u["expression"] = kink->expression;
      u["reason"] = kink->reason;
      r["undefined"] = std::move(u);
    }
    results.push_back(std::move(r));
  }
  return results;
}

Json law_evaluation_json(const law::Law& l, const std::string& parameter, std::span<const double> ts, int order) {
  Json out = Json::object();
  out["expression"] = law::print(l);
  out["parameter"] = parameter;
  out["dimension"] = l.dimension();
  if (!ts.empty())
    out["results"] = law_results_to_json(ts, law_derivatives(l, parameter, ts, order), l.dimension(), order);
  return out;
}

Json law_request_json(const Json& body) {
  const json::JsonPath root;
  json::reject_unknown_members(body, root, {"expression", "parameter", "at", "derivatives"});
  const std::string expression =
      json::get_string(json::require_member(body, root, "expression"), json::root_path("expression"));
  std::string parameter = "t";
  if (const Json* p = json::optional_member(body, "parameter"))
    parameter = json::get_string(*p, json::root_path("parameter"));
  int order = 0;
  if (const Json* d = json::optional_member(body, "derivatives"))
    order = static_cast<int>(json::get_integer(*d, json::root_path("derivatives"), 0, 16));
  std::vector<double> ts;
  if (const Json* at = json::optional_member(body, "at")) ts = json::get_number_array(*at, json::root_path("at"));
  law::Context ctx;
  law::ParseOptions po;
  po.parameters = {parameter};
  const law::Law l = law::parse(expression, ctx, po);
  Json out = law_evaluation_json(l, parameter, ts, order);
  // The route always answers "results" (empty without "at").
  if (!out.contains("results")) out["results"] = Json::array();
  return out;
}

}  // namespace hula::io
