// SPDX-License-Identifier: MIT
#include "hula/optim/solution.hpp"

#include <cmath>
#include <string>

#include "hula/core/error.hpp"

namespace hula::optim {

void RunSettings::validate() const {
  if (!std::isfinite(penalty) || penalty < 0.0) {
    throw Error(Errc::InvalidOption, "run.penalty = " + format_number(penalty) + " must be finite and >= 0",
                {.field = "run.penalty"});
  }
  stop.validate();
}

void RunSettings::validate_initial(std::span<const Variable> variables, std::size_t population) const {
  if (initial.size() > population)
    throw Error(Errc::InvalidOption,
                "run.initial has " + std::to_string(initial.size()) + " individuals, more than the population " +
                    std::to_string(population),
                {.field = "run.initial"});
  for (std::size_t i = 0; i < initial.size(); ++i) {
    const std::string name = "run.initial[" + std::to_string(i) + "]";
    if (initial[i].size() != variables.size())
      throw Error(Errc::InvalidOption,
                  name + " has " + std::to_string(initial[i].size()) + " values, the problem " +
                      std::to_string(variables.size()) + " variables",
                  {.field = "run.initial", .index = i});
    for (std::size_t j = 0; j < variables.size(); ++j)
      if (!(initial[i][j] >= variables[j].lower && initial[i][j] <= variables[j].upper))
        throw Error(Errc::InvalidOption,
                    name + " value " + format_number(initial[i][j]) + " of variable " + std::to_string(j) +
                        " is outside its bounds [" + format_number(variables[j].lower) + ", " +
                        format_number(variables[j].upper) + "]",
                    {.field = "run.initial", .index = i, .component = j});
  }
}

}  // namespace hula::optim
