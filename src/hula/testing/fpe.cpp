// SPDX-License-Identifier: MIT
#include "hula/testing/fpe.hpp"

#include <fenv.h>

namespace hula::testing {

void enable_fpe_traps() {
  feclearexcept(FE_ALL_EXCEPT);
  feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
}

FpeGuard::FpeGuard() : saved_(fegetexcept()) {
  fegetenv(&env_);
  fedisableexcept(FE_ALL_EXCEPT);
}

FpeGuard::~FpeGuard() {
  feclearexcept(FE_ALL_EXCEPT);
  feenableexcept(saved_);
}

}  // namespace hula::testing
