// SPDX-License-Identifier: MIT
// The AVX-512F run kernels (eight doubles per vector). Compiled with -mavx512f -ffp-contract=off and
// nothing but span_eval.hpp, so no inline function of another header is emitted here with AVX-512
// instructions.
#define HULA_SPAN_ISA avx512
#include "hula/nurbs/detail/span_eval.hpp"

namespace hula::nurbs::detail {

using RunKernel = std::size_t (*)(const double*, double, double, double, double, const double*, std::size_t, double*);

RunKernel run_kernel_avx512(int degree, bool rational, int order) noexcept {
  return avx512::run_kernel<8>(degree, rational, order);
}

using SpeedKernel = bool (*)(const double*, double, double, const double*, std::size_t, double*);

SpeedKernel speed_kernel_avx512(int degree, bool rational) noexcept {
  return avx512::speed_kernel<8>(degree, rational);
}

}  // namespace hula::nurbs::detail
