// SPDX-License-Identifier: MIT
// Design by curvature on a curve entity: the entity's curve
// replaced by studies::edit_curvature's result inside the caller's
// transaction, so the edit is one undo step and a failure changes nothing.
// Every door (the server's curvature-edit route, scripts through the
// document) calls this; `hula reconstruct --curve` calls the same library
// function on a curve file.
#pragma once

#include "hula/oli/document.hpp"
#include "hula/studies/curvature_edit.hpp"

namespace hula::oli {

/// Edits the curvature profile of the curve entity `label` and stores the result.
/// Example:
/// ```
/// std::optional<studies::CurvatureEditResult> r;
/// doc.transact("edit curvature", [&](Edit& e) { r = edit_curvature(e, label, edit); }).throw_if_failed();
/// ```
/// @param edit the transaction's editing handle
/// @param label a curve entity, not locked
/// @param change the target or change of κ (and τ) as laws of the curve's arc length
/// @param options what the end keeps, the handle budget, tolerances
/// @returns the edit's report; the entity now holds its curve
/// @throws hula::Error(Errc::InvalidArgument) naming the label if the entity is not a curve or is locked
/// @throws as studies::edit_curvature (the transaction then rolls back)
studies::CurvatureEditResult edit_curvature(Edit& edit, Label label, const studies::CurvatureEdit& change,
                                            const studies::CurvatureEditOptions& options = {});

}  // namespace hula::oli
