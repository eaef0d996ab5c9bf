// SPDX-License-Identifier: MIT
// The portable run kernels (two doubles per vector: SSE2 on x86-64) and the choice among the variants
// by hula::simd_level(). The wider variants live in span_simd_avx2.cpp and span_simd_avx512.cpp
// (x86-64 only), each compiled for its own instruction set.
#include "hula/nurbs/detail/span_simd.hpp"

#include "hula/core/simd.hpp"

#define HULA_SPAN_ISA baseline
#include "hula/nurbs/detail/span_eval.hpp"
#undef HULA_SPAN_ISA

namespace hula::nurbs::detail {

RunKernel run_kernel_baseline(int degree, bool rational, int order) noexcept {
  return baseline::run_kernel<2>(degree, rational, order);
}

SpeedKernel speed_kernel_baseline(int degree, bool rational) noexcept {
  return baseline::speed_kernel<2>(degree, rational);
}

#if !defined(HULA_SIMD_X86)
RunKernel run_kernel_avx2(int, bool, int) noexcept { return nullptr; }
RunKernel run_kernel_avx512(int, bool, int) noexcept { return nullptr; }
SpeedKernel speed_kernel_avx2(int, bool) noexcept { return nullptr; }
SpeedKernel speed_kernel_avx512(int, bool) noexcept { return nullptr; }
#endif

RunKernel run_kernel(int degree, bool rational, int order) noexcept {
  switch (simd_level()) {
    case SimdLevel::Scalar:
      return nullptr;
    case SimdLevel::Baseline:
      return run_kernel_baseline(degree, rational, order);
    case SimdLevel::Avx2:
      return run_kernel_avx2(degree, rational, order);
    case SimdLevel::Avx512:
      return run_kernel_avx512(degree, rational, order);
  }
  return nullptr;
}

SpeedKernel speed_kernel(int degree, bool rational) noexcept {
  switch (simd_level()) {
    case SimdLevel::Scalar:
      return nullptr;
    case SimdLevel::Baseline:
      return speed_kernel_baseline(degree, rational);
    case SimdLevel::Avx2:
      return speed_kernel_avx2(degree, rational);
    case SimdLevel::Avx512:
      return speed_kernel_avx512(degree, rational);
  }
  return nullptr;
}

}  // namespace hula::nurbs::detail
