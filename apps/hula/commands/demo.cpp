// SPDX-License-Identifier: MIT
// `hula demo`: the thesis's example curves and their
// analysis as JSON (io::thesis_examples_json) —
//  * 7.1.2 / eq. 29: the chord-length cubic spline through (0,0,0), (40,25,0),
//    (80,-25,0), (120,0,0) with its cumulative chord lengths 47.17, 111.20, 158.37,
//    and the asymmetric variant with (80,-40,0);
//  * 7.1.2: the 6-point control polygon as a cubic B-spline with the ACIS knots
//    {0,0,0,0.33,0.66,1,1,1}, and with the double knot {0,0,0,0.33,0.33,1,1,1},
//    whose left/right derivative table at the double knot reproduces the layout
//    of Table 3 (C1 but not C2 there).
#include "commands/common.hpp"
#include "hula/io/curve_queries.hpp"

namespace hula::cli {

int run_demo() {
  print_json(io::thesis_examples_json());
  return kExitOk;
}

Command add_demo(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("demo", "Analyse the thesis's example curves");
  return {sub, [] { return run_demo(); }};
}

}  // namespace hula::cli
