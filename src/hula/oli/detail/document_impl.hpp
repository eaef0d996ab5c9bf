// SPDX-License-Identifier: MIT
// The document's state (document.cpp) shared with the Edit methods (edit.cpp).
#pragma once

#include <deque>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hula/oli/detail/entity_state.hpp"
#include "hula/oli/document.hpp"
#include "hula/oli/store/store.hpp"

namespace hula::oli {

namespace detail {

/// One entity's change in an undo step: its state before and after (null: absent).
struct Change {
  Label label{};
  StatePtr before{};
  StatePtr after{};
};

/// One undo step.
struct Step {
  std::uint64_t revision = 0;
  std::string name{};
  std::string time{};
  /// Ascending labels.
  std::vector<Change> changes{};
};

}  // namespace detail

struct Document::Impl {
  DocumentOptions options{};
  std::map<Label, detail::StatePtr> entities{};
  std::uint64_t next_label = 1;
  std::uint64_t revision = 0;
  /// Applied steps, oldest first (back: the latest, revision == `revision`).
  std::deque<detail::Step> undo{};
  /// Undone steps, the next to redo at the back.
  std::vector<detail::Step> redo{};
  std::optional<store::Store> store{};
  std::filesystem::path path{};
  bool read_only = false;
  std::string created{};

  /// Nesting depth of transact (0: none running).
  int depth = 0;
  /// Every entity write of the running transaction, in order: the label and its state before the write.
  std::vector<std::pair<Label, detail::StatePtr>> journal{};

  std::vector<std::pair<ObserverId, Observer>> observers{};
  ObserverId next_observer = 1;

  /// The current state of `label`, or null.
  [[nodiscard]] detail::StatePtr state(Label label) const {
    const auto it = entities.find(label);
    return it == entities.end() ? nullptr : it->second;
  }
  /// The state of an existing entity.
  /// @throws hula::Error(Errc::InvalidArgument) naming the label when there is none
  [[nodiscard]] const detail::StatePtr& existing(Label label) const;
  /// Writes `label`'s state (null removes it), journalling the previous one.
  void put(Label label, detail::StatePtr next);
  /// Undoes journal entries back to `mark`.
  void rollback_to(std::size_t mark);
};

}  // namespace hula::oli
