// SPDX-License-Identifier: MIT
// The AVX-512F sample kernels (8 doubles per vector). Compiled with -mavx512f -ffp-contract=off and
// nothing but profile_kernel.hpp, so no inline function of another header is emitted here with wide
// instructions.
#define HULA_PROFILE_ISA avx512
#include "hula/studies/detail/profile_kernel.hpp"

namespace hula::studies::detail {

using ProfileKernel = double (*)(const double*, const double*, const unsigned*, const double*, std::size_t, double*,
                                 double*);

ProfileKernel profile_kernel_avx512(int dimension, bool torsion) noexcept {
  return avx512::profile_kernel<8>(dimension, torsion);
}

}  // namespace hula::studies::detail
