// SPDX-License-Identifier: MIT
// Small helpers shared by the law tests: evaluate a law at one parameter value
// through a freshly compiled tape.
#pragma once

#include <string>
#include <vector>

#include "hula/law/tape.hpp"

namespace hula::law::test {

/// Components of `law` at parameter `name` = value (NaN components where undefined).
inline std::vector<double> eval(const Law& law, double value, const std::string& name = "t") {
  const std::string inputs[1] = {name};
  const Law outs[1] = {law};
  const Tape tape = Tape::compile(outs, inputs);
  std::vector<double> out(tape.output_count());
  (void)tape.evaluate(std::span<const double>(&value, 1), out);
  return out;
}

/// Scalar value of a scalar law.
inline double eval1(const Law& law, double value, const std::string& name = "t") { return eval(law, value, name)[0]; }

}  // namespace hula::law::test
