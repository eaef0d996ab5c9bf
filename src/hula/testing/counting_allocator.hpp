// SPDX-License-Identifier: MIT
// Counting global allocator for the "no allocation per point" checks (DESIGN:
// hot loops are checked with a counting allocator in a unit test, never with
// timing). Every test binary that links hula::testing gets these replacement
// global operator new/delete (the archive member is pulled in to resolve
// operator new before libstdc++ is searched); counting costs one relaxed
// atomic increment per allocation. Do not define another replacement in a test.
#pragma once

namespace hula::testing {

/// Number of global operator new calls so far in this process.
[[nodiscard]] long allocation_count() noexcept;

}  // namespace hula::testing
