// SPDX-License-Identifier: MIT
// The run kernels of NurbsCurve's batch evaluation for each instruction set of
// hula/core/simd.hpp: detail/span_eval.hpp compiled for the portable baseline (span_simd.cpp) and, on
// x86-64, for AVX2 and AVX-512F (span_simd_avx2.cpp, span_simd_avx512.cpp). Every variant gives
// bit-identical results (span_eval.hpp), so the level changes speed only.
#pragma once

#include <cstddef>

namespace hula::nurbs::detail {

/// Evaluates points of one span, several at a time, from ts[0] on while they lie strictly inside the
/// open span (lo, hi): coefficients of the span, its midpoint and 1 / half-length, the span's ends, n
/// parameters, out 3 (order + 1) doubles per point. Returns how many points it evaluated.
using RunKernel = std::size_t (*)(const double* coef, double mid, double scale, double lo, double hi, const double* ts,
                                  std::size_t n, double* out);

/// The run kernel for (degree, rational, order) at hula::simd_level(); nullptr = evaluate point by point.
[[nodiscard]] RunKernel run_kernel(int degree, bool rational, int order) noexcept;

// The variants (defined in span_simd*.cpp; nullptr outside degrees 2…5 and orders 0…3).
RunKernel run_kernel_baseline(int degree, bool rational, int order) noexcept;
RunKernel run_kernel_avx2(int degree, bool rational, int order) noexcept;
RunKernel run_kernel_avx512(int degree, bool rational, int order) noexcept;

}  // namespace hula::nurbs::detail
