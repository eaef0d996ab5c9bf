// SPDX-License-Identifier: MIT
// The AVX2 sample kernels (4 doubles per vector). Compiled with -mavx2 -ffp-contract=off and
// nothing but profile_kernel.hpp, so no inline function of another header is emitted here with wide
// instructions.
#define HULA_PROFILE_ISA avx2
#include "hula/studies/detail/profile_kernel.hpp"

namespace hula::studies::detail {

using ProfileKernel = double (*)(const double*, const double*, const unsigned*, const double*, std::size_t, double*,
                                 double*);

ProfileKernel profile_kernel_avx2(int dimension, bool torsion) noexcept {
  return avx2::profile_kernel<4>(dimension, torsion);
}

}  // namespace hula::studies::detail
