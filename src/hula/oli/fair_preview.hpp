// SPDX-License-Identifier: MIT
// The fairing preview of an entity: the fairing assistant's
// ghost of a curve entity (studies::fair_within_tolerance), computed from an
// immutable Entity snapshot so a caller can read the entity under a document
// lock and compute with no lock held. Nothing in the document changes; a
// client accepts the ghost by replacing the entity's curve (one transaction).
#pragma once

#include "hula/oli/document.hpp"
#include "hula/studies/fairing_assistant.hpp"

namespace hula::oli {

/// The faired ghost of a curve entity, within `options.tolerance`.
/// @param entity a Curve entity, as read from a document (a snapshot: no lock is needed)
/// @param options method, tolerance, time budget
/// @param edit when given, the curve faired instead of the entity's (an edit of it still in flight, as a drag's
///   latest position); the entity must still be a curve
/// @returns the ghost and how it compares with the entity's curve (studies::AssistantResult)
/// @throws hula::Error(Errc::InvalidArgument) naming the label if the entity is not a curve
/// @throws as studies::fair_within_tolerance (a law or natural curve, bad options)
[[nodiscard]] studies::AssistantResult fair_preview(const Entity& entity, const studies::AssistantOptions& options,
                                                    const curve::Curve* edit = nullptr);

}  // namespace hula::oli
