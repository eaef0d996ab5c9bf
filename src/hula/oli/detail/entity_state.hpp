// SPDX-License-Identifier: MIT
// The immutable state of one entity at one revision. Documents, undo records
// and Entity views share these by pointer; a change makes a new state (the
// big parts — the curve, the points, the study — are shared again unless they
// changed), so an undo step costs the size of what it changed.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "hula/oli/document.hpp"

namespace hula::oli::detail {

struct EntityState {
  EntityKind kind = EntityKind::Curve;
  Attributes attributes{};
  std::optional<Provenance> provenance{};
  std::vector<Constraint> constraints{};
  std::shared_ptr<const curve::Curve> curve{};
  std::shared_ptr<const PointSet> points{};
  std::shared_ptr<const Study> study{};
};

using StatePtr = std::shared_ptr<const EntityState>;

}  // namespace hula::oli::detail
