// SPDX-License-Identifier: MIT
// The AVX2 run kernels (four doubles per vector). Compiled with -mavx2 -ffp-contract=off and nothing
// but span_eval.hpp, so no inline function of another header is emitted here with AVX2 instructions.
#define HULA_SPAN_ISA avx2
#include "hula/nurbs/detail/span_eval.hpp"

namespace hula::nurbs::detail {

using RunKernel = std::size_t (*)(const double*, double, double, double, double, const double*, std::size_t, double*);

RunKernel run_kernel_avx2(int degree, bool rational, int order) noexcept {
  return avx2::run_kernel<4>(degree, rational, order);
}

using SpeedKernel = bool (*)(const double*, double, double, const double*, std::size_t, double*);

SpeedKernel speed_kernel_avx2(int degree, bool rational) noexcept { return avx2::speed_kernel<4>(degree, rational); }

}  // namespace hula::nurbs::detail
