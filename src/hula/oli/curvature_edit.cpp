// SPDX-License-Identifier: MIT
// Design by curvature on a curve entity (curvature_edit.hpp).
#include "hula/oli/curvature_edit.hpp"

namespace hula::oli {

studies::CurvatureEditResult edit_curvature(Edit& edit, Label label, const studies::CurvatureEdit& change,
                                            const studies::CurvatureEditOptions& options) {
  const Entity entity = edit.get(label);
  studies::CurvatureEditResult r = studies::edit_curvature(entity.curve(), change, options);
  edit.set_curve(label, r.curve);  // refuses a locked entity, naming its label
  return r;
}

}  // namespace hula::oli
