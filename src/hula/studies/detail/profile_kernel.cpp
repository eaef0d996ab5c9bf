// SPDX-License-Identifier: MIT
// The portable sample kernels (two doubles per vector: SSE2 on x86-64) and the choice among the
// variants by hula::simd_level(); the wider ones are in profile_kernel_avx2.cpp and _avx512.cpp.
#include "hula/core/simd.hpp"
#include "hula/studies/detail/profile_kernel_select.hpp"

#define HULA_PROFILE_ISA baseline
#include "hula/studies/detail/profile_kernel.hpp"
#undef HULA_PROFILE_ISA
#define HULA_PROFILE_ISA scalar
#include "hula/studies/detail/profile_kernel.hpp"
#undef HULA_PROFILE_ISA

namespace hula::studies::detail {

#if !defined(HULA_SIMD_X86)
ProfileKernel profile_kernel_avx2(int, bool) noexcept { return nullptr; }
ProfileKernel profile_kernel_avx512(int, bool) noexcept { return nullptr; }
#endif

ProfileKernel profile_kernel(int dimension, bool torsion) noexcept {
  switch (simd_level()) {
    case SimdLevel::Scalar:
      return scalar::profile_kernel<1>(dimension, torsion);
    case SimdLevel::Baseline:
      return baseline::profile_kernel<2>(dimension, torsion);
    case SimdLevel::Avx2:
      return profile_kernel_avx2(dimension, torsion);
    case SimdLevel::Avx512:
      return profile_kernel_avx512(dimension, torsion);
  }
  return scalar::profile_kernel<1>(dimension, torsion);
}

}  // namespace hula::studies::detail
