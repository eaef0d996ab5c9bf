// SPDX-License-Identifier: MIT
// `hula log-aesthetic --alpha A --rho0 R --lambda L --length S`: the log-aesthetic curve segment of
// slope α (intrinsic/log_aesthetic.hpp, Yoshida & Saito 2006) as an exact curve value (a natural
// curve: κ(s) = (ρ0^α + αλs)^(−1/α) from its law, the position integrated), printed at --at with its
// curvature and dκ/ds as the analysis computes them (diffgeom::frenet of the curve value), and written
// by its law with -o (or as a NURBS with --to-nurbs TOL). JSON out:
// {"alpha", "rho0", "lambda", "length", "max_length", "curvature" (the law), "points": [{"s", "point",
// "tangent", "kappa", "kappa_prime"}], "output"?} (io::log_aesthetic_answer).
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/exact_curves.hpp"

namespace hula::cli {

namespace {

struct LogAestheticArgs {
  std::optional<double> alpha, rho0, lambda, length, start_angle, to_nurbs;
  std::string start_point, at, output;
  double tolerance = curve::kNaturalTolerance;
};

int run_log_aesthetic(const LogAestheticArgs& a) {
  if (!a.output.empty()) io::check_output_path(a.output, "--output");
  io::LogAestheticRequest q{.alpha = *a.alpha, .rho0 = *a.rho0, .lambda = *a.lambda, .length = *a.length};
  if (!a.start_point.empty()) {
    const std::vector<double> p = parse_number_list(a.start_point, "start-point");
    if (p.size() != 2)
      throw Error(Errc::InvalidArgument,
                  "--start-point needs 2 numbers x,y (a planar point), got " + std::to_string(p.size()),
                  ErrorWhere{.field = "start-point"});
    q.start_point = {p[0], p[1], 0.0};
  }
  q.start_angle = a.start_angle.value_or(0.0);
  if (!a.at.empty()) q.at = parse_number_list(a.at, "at");
  q.tolerance = a.tolerance;
  io::LogAestheticAnswer answer = io::log_aesthetic_answer(q);
  Json doc = std::move(answer.json);
  if (!a.output.empty()) doc["output"] = io::write_exact_curve(a.output, answer.curve, a.to_nurbs);
  print_result(doc, a.output);
  return kExitOk;
}

}  // namespace

Command add_log_aesthetic(CLI::App& app) {
  auto a = std::make_shared<LogAestheticArgs>();
  CLI::App* sub = app.add_subcommand(
      "log-aesthetic", "A log-aesthetic curve segment of slope alpha (straight logarithmic curvature graph), exact");
  constexpr double kMax = std::numeric_limits<double>::max();
  add_real_option(sub, "--alpha", a->alpha, -kMax, kMax, false,
                  "Slope alpha of the logarithmic curvature graph (-1 clothoid, 1 logarithmic spiral, 2 involute)")
      ->required();
  add_real_option(sub, "--rho0", a->rho0, 0.0, kMax, true, "Radius of curvature at s = 0, > 0")->required();
  add_real_option(sub, "--lambda", a->lambda, -kMax, kMax, false,
                  "Rate lambda: rho^alpha = rho0^alpha + alpha*lambda*s (rho = rho0*exp(lambda*s) for alpha = 0)")
      ->required();
  add_real_option(sub, "--length", a->length, 0.0, kMax, true, "Arc length L > 0 (below the family's end)")->required();
  sub->add_option("--start-point", a->start_point, "Start point x,y (default 0,0)");
  add_real_option(sub, "--start-angle", a->start_angle, -kMax, kMax, false,
                  "Start tangent angle, radians from +x (default 0); the curve turns left (kappa > 0)");
  sub->add_option("--at", a->at, "Arc lengths s0,s1,... to print (default 0, L/2, L)");
  add_exact_output_options(sub, a->output, a->to_nurbs, a->tolerance);
  return {sub, [a] { return run_log_aesthetic(*a); }};
}

}  // namespace hula::cli
