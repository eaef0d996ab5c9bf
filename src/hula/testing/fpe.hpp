// SPDX-License-Identifier: MIT
// Floating-point exception traps for Debug test binaries, and a scoped guard
// that suspends them around code whose NaN results are documented.
#pragma once

#include <cfenv>

namespace hula::testing {

/// Traps FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW (glibc feenableexcept).
void enable_fpe_traps();

/// Disables the traps for its lifetime and restores the previous mask.
class FpeGuard {
 public:
  FpeGuard();
  ~FpeGuard();
  FpeGuard(const FpeGuard&) = delete;
  FpeGuard& operator=(const FpeGuard&) = delete;

 private:
  int saved_;
  std::fenv_t env_{};
};

}  // namespace hula::testing
