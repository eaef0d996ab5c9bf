// SPDX-License-Identifier: MIT
// Law values and derivatives at parameters (io/law_values.hpp): one compiled
// tape for the law and its derivatives, evaluated point by point so that the
// first undefined point is named.
#include "hula/io/law_values.hpp"

#include "hula/core/error.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/singularities.hpp"
#include "hula/law/tape.hpp"

namespace hula::io {

std::vector<std::vector<double>> law_derivatives(const law::Law& l, const std::string& parameter,
                                                 std::span<const double> ts, int order) {
  const std::vector<law::Law> laws = law::derivatives(l, parameter, order);
  const std::string in[1] = {parameter};
  const law::Tape tape = law::Tape::compile(laws, in);
  std::vector<std::vector<double>> out;
  law::Workspace w = tape.make_workspace();
  for (std::size_t i = 0; i < ts.size(); ++i) {
    std::vector<double> v(tape.output_count());
    if (!tape.evaluate(ts.subspan(i, 1), v, w)) {
      // Name the innermost undefined subexpression (of the law or of the derivative that failed).
      std::string why;
      for (const law::Law& d : laws)
        if (auto cause = law::explain_undefined(d, parameter, ts[i])) {
          why = " (" + cause->expression + ": " + cause->reason + ")";
          break;
        }
      throw Error(Errc::OutOfDomain,
                  parameter + "[" + std::to_string(i) + "] = " + format_number(ts[i]) +
                      (order == 0 ? std::string(": the law is undefined there")
                                  : ": the law or one of its first " + std::to_string(order) +
                                        " derivatives is undefined there") +
                      why,
                  ErrorWhere{.field = parameter, .index = i});
    }
    out.push_back(std::move(v));
  }
  return out;
}

Json law_results_to_json(std::span<const double> ts, const std::vector<std::vector<double>>& values, int dimension,
                         int order) {
  Json results = Json::array();
  const auto d = static_cast<std::size_t>(dimension);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    Json ders = Json::array();
    for (std::size_t k = 0; k <= static_cast<std::size_t>(order); ++k) {
      Json v = Json::array();
      for (std::size_t c = 0; c < d; ++c) v.push_back(values[i][k * d + c]);
      ders.push_back(std::move(v));
    }
    Json r = Json::object();
    r["t"] = ts[i];
    r["derivatives"] = std::move(ders);
    results.push_back(std::move(r));
  }
  return results;
}
}  // namespace hula::io
