// SPDX-License-Identifier: MIT
#include "hula/optim/run_report.hpp"

#include <cmath>

#include "hula/core/error.hpp"

namespace hula::optim {

std::string_view termination_name(Termination reason) noexcept {
  switch (reason) {
    case Termination::MaxGenerations:
      return "MaxGenerations";
    case Termination::MaxEvaluations:
      return "MaxEvaluations";
    case Termination::TargetReached:
      return "TargetReached";
    case Termination::Stagnation:
      return "Stagnation";
    case Termination::WallTime:
      return "WallTime";
    case Termination::Cancelled:
      return "Cancelled";
    case Termination::Converged:
      return "Converged";
  }
  return "Unknown";
}

std::optional<Termination> termination_from_name(std::string_view name) noexcept {
  for (const Termination t :
       {Termination::MaxGenerations, Termination::MaxEvaluations, Termination::TargetReached, Termination::Stagnation,
        Termination::WallTime, Termination::Cancelled, Termination::Converged})
    if (termination_name(t) == name) return t;
  return std::nullopt;
}

void StopCriteria::validate() const {
  if (target && !std::isfinite(*target)) {
    throw Error(Errc::InvalidOption, "stop.target = " + format_number(*target) + " must be finite",
                {.field = "stop.target"});
  }
  if (!std::isfinite(stagnation_tolerance) || stagnation_tolerance < 0.0) {
    throw Error(Errc::InvalidOption,
                "stop.stagnation_tolerance = " + format_number(stagnation_tolerance) + " must be finite and >= 0",
                {.field = "stop.stagnation_tolerance"});
  }
  if (!std::isfinite(wall_time_seconds) || wall_time_seconds < 0.0) {
    throw Error(Errc::InvalidOption,
                "stop.wall_time_seconds = " + format_number(wall_time_seconds) + " must be finite and >= 0",
                {.field = "stop.wall_time_seconds"});
  }
}

}  // namespace hula::optim
