// SPDX-License-Identifier: MIT
#include "hula/studies/fair_knots_study.hpp"

namespace hula::studies {

std::string_view fairing_method_name(FairingMethod method) noexcept {
  switch (method) {
    case FairingMethod::None:
      return "none";
    case FairingMethod::Ga:
      return "ga";
    case FairingMethod::Deterministic:
      return "deterministic";
    case FairingMethod::Both:
      break;
  }
  return "both";
}

}  // namespace hula::studies
