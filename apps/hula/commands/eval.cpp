// SPDX-License-Identifier: MIT
// `hula eval`: positions and derivatives of a curve file at given parameters,
// as {"results": [{"t": t, "derivatives": [[C], [C'], ...]}]}.
#include <algorithm>
#include <memory>

#include "commands/common.hpp"
#include "hula/core/error.hpp"

namespace hula::cli {

namespace {
struct EvalArgs {
  std::string curve;
  std::string at;
  int derivatives = 0;
  std::string side = "right";
  bool extrapolate = false;
  bool clamp = false;
};

int run_eval(const EvalArgs& a) {
  const curve::Curve c = io::read_curve_file(a.curve);
  const std::vector<double> ts = parse_number_list(a.at, "t");
  nurbs::EvalOptions options;
  options.side = a.side == "left" ? nurbs::Side::Left : nurbs::Side::Right;
  options.domain =
      a.extrapolate ? nurbs::Domain::Extrapolate : (a.clamp ? nurbs::Domain::Clamp : nurbs::Domain::Strict);
  const auto per_t = static_cast<std::size_t>(a.derivatives) + 1;
  std::vector<Vec3> out(ts.size() * per_t);
  if (!c.law()) {
    // The batch form names the index of a bad parameter ("t[2] = 1.5 is outside ...").
    c.derivatives(ts, a.derivatives, out, options);
  } else {
    // Law curves are evaluated exactly from the law, not from their stand-in NURBS, to any order.
    std::vector<double> us = ts;
    const Interval dom = c.domain();
    for (std::size_t i = 0; i < us.size(); ++i) {
      if (dom.contains(us[i]) || options.domain == nurbs::Domain::Extrapolate) continue;
      if (options.domain == nurbs::Domain::Clamp) {
        us[i] = std::clamp(us[i], dom.start, dom.end);
        continue;
      }
      throw Error(Errc::OutOfDomain,
                  "t[" + std::to_string(i) + "] = " + format_number(us[i]) + " is outside the domain [" +
                      format_number(dom.start) + ", " + format_number(dom.end) + "]",
                  ErrorWhere{.field = "t", .index = i});
    }
    Json doc = Json::object();
    doc["results"] = law_results_to_json(ts, law_derivatives(*c.law(), c.law_parameter(), us, a.derivatives),
                                         c.law()->dimension(), a.derivatives);
    print_json(doc);
    return kExitOk;
  }
  const int dim = c.dimension();
  Json results = Json::array();
  for (std::size_t i = 0; i < ts.size(); ++i) {
    Json ders = Json::array();
    for (std::size_t k = 0; k < per_t; ++k) ders.push_back(vec_to_json(out[i * per_t + k], dim));
    Json r = Json::object();
    r["t"] = ts[i];
    r["derivatives"] = std::move(ders);
    results.push_back(std::move(r));
  }
  Json doc = Json::object();
  doc["results"] = std::move(results);
  print_json(doc);
  return kExitOk;
}
}  // namespace

Command add_eval(CLI::App& app) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* sub = app.add_subcommand("eval", "Evaluate a curve file: position and derivatives at parameters");
  sub->add_option("curve", args->curve, "Curve file (JSON)")->required();
  sub->add_option("--at", args->at, "Parameters t0,t1,... inside the domain")->required();
  sub->add_option("--derivatives", args->derivatives,
                  "Highest derivative order N in [0, 1000] (default 0: position only)")
      ->check(CLI::Range(0, 1000));
  sub->add_option("--side", args->side, "One-sided limit at knots: left | right (default right)")
      ->check(CLI::IsMember({"left", "right"}));
  auto* ex = sub->add_flag("--extrapolate", args->extrapolate, "Continue the end pieces outside the domain");
  auto* cl = sub->add_flag("--clamp", args->clamp, "Evaluate outside parameters at the nearest domain end");
  ex->excludes(cl);
  return {sub, [args] { return run_eval(*args); }};
}

}  // namespace hula::cli
