// SPDX-License-Identifier: MIT
// `hula eval`: positions and derivatives of a curve file at given parameters,
// as {"results": [{"t": t, "derivatives": [[C], [C'], ...]}]}.
#include <algorithm>
#include <memory>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/json_write.hpp"
#include "hula/io/law_values.hpp"

namespace hula::cli {

namespace {
struct EvalArgs {
  std::string curve;
  std::string at;
  int derivatives = 0;
  std::string side = "right";
  bool extrapolate = false;
  bool clamp = false;
  std::string format = "json";
};

// Prints {"results": ...} or, in the other --formats, the table of io::derivative_table: one record per
// line (jsonl), CSV rows "t,x,y[,z],dx,dy[,dz],..." under a comment line "# t x y z dx ..." (no commas: it
// survives `cut -d, -f2-`, after which the rows read back as a points file), or text lines
// "t = 0.5: [x, y, z] [dx, dy, dz]".
void print_results(const Json& results, int dimension, int derivatives, std::string_view format) {
  Json doc = Json::object();
  doc["results"] = results;
  print_formatted(doc, format, [&](const Json& d) {
    return io::derivative_table(d["results"], static_cast<std::size_t>(dimension),
                                static_cast<std::size_t>(derivatives));
  });
}

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
    // The batch form names the index of a bad parameter ("t[2] = 1.5 is outside ..."); its hint names
    // the library's Domain values, which a CLI user asks for with --extrapolate or --clamp.
    try {
      c.derivatives(ts, a.derivatives, out, options);
    } catch (const Error& e) {
      std::string message = e.message();
      constexpr std::string_view kLibraryHint = "(ask for Domain::Extrapolate or Domain::Clamp by name)";
      if (const auto at = message.find(kLibraryHint); at != std::string::npos)
        message.replace(at, kLibraryHint.size(), "(give --extrapolate or --clamp to evaluate outside it)");
      throw Error(e.code(), message, e.where());
    }
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
    print_results(io::law_results_to_json(ts, io::law_derivatives(*c.law(), c.law_parameter(), us, a.derivatives),
                                          c.law()->dimension(), a.derivatives),
                  static_cast<int>(c.law()->dimension()), a.derivatives, a.format);
    return kExitOk;
  }
  const int dim = c.dimension();
  Json results = Json::array();
  for (std::size_t i = 0; i < ts.size(); ++i) {
    Json ders = Json::array();
    for (std::size_t k = 0; k < per_t; ++k) ders.push_back(io::point_to_json(out[i * per_t + k], dim));
    Json r = Json::object();
    r["t"] = ts[i];
    r["derivatives"] = std::move(ders);
    results.push_back(std::move(r));
  }
  print_results(results, dim, a.derivatives, a.format);
  return kExitOk;
}
}  // namespace

Command add_eval(CLI::App& app) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* sub = app.add_subcommand("eval", "Evaluate a curve file: position and derivatives at parameters");
  sub->add_option("curve", args->curve, "Curve file (JSON); - reads stdin")->required();
  sub->add_option("--at", args->at, "Parameters t0,t1,... inside the domain")->required();
  sub->add_option("--derivatives", args->derivatives,
                  "Highest derivative order N in [0, 1000] (default 0: position only)")
      ->check(CLI::Range(0, 1000));
  sub->add_option("--side", args->side, "One-sided limit at knots: left | right (default right)")
      ->check(CLI::IsMember({"left", "right"}));
  auto* ex = sub->add_flag("--extrapolate", args->extrapolate, "Continue the end pieces outside the domain");
  auto* cl = sub->add_flag("--clamp", args->clamp, "Evaluate outside parameters at the nearest domain end");
  ex->excludes(cl);
  sub->add_option("--format", args->format,
                  "json (default) | jsonl (one result per line) | csv (t,x,y,z,dx,... rows) | text")
      ->check(CLI::IsMember({"json", "jsonl", "csv", "text"}));
  return {sub, [args] { return run_eval(*args); }};
}

}  // namespace hula::cli
