// SPDX-License-Identifier: MIT
// The fairing preview of an entity (fair_preview.hpp).
#include "hula/oli/fair_preview.hpp"

namespace hula::oli {

studies::AssistantResult fair_preview(const Entity& entity, const studies::AssistantOptions& options) {
  return studies::fair_within_tolerance(entity.curve(), options);
}

}  // namespace hula::oli
