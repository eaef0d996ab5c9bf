// SPDX-License-Identifier: MIT
// Counting global allocator for the "no allocation per point" checks (DESIGN:
// hot loops are checked with a counting allocator in a unit test, never with
// timing). Linking a test that calls allocation_count() pulls in replacement
// global operator new/delete that count every allocation.
#pragma once

namespace hula::testing {

/// Number of global operator new calls so far in this process.
[[nodiscard]] long allocation_count() noexcept;

}  // namespace hula::testing
