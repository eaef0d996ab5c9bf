// SPDX-License-Identifier: MIT
// The fairing preview of an entity (fair_preview.hpp).
#include "hula/oli/fair_preview.hpp"

namespace hula::oli {

studies::AssistantResult fair_preview(const Entity& entity, const studies::AssistantOptions& options,
                                      const curve::Curve* edit) {
  const curve::Curve& stored = entity.curve();  // refuses a non-curve entity, naming its label
  return studies::fair_within_tolerance(edit != nullptr ? *edit : stored, options);
}

}  // namespace hula::oli
