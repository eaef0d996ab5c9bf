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

/// The speed |C'| at n parameters (n a multiple of 16), all strictly inside one span (coefficients, midpoint,
/// 1 / half-length): norm() of the first derivative the run kernel gives, into out. Returns false when
/// some point's |C'|² is outside (1e-290, 1e290), where norm() scales (those values are then not norm's).
using SpeedKernel = bool (*)(const double* coef, double mid, double scale, const double* ts, std::size_t n,
                             double* out);

/// The speed kernel for (degree, rational) at hula::simd_level(); nullptr = none (scalar level, degree
/// outside 2…5).
[[nodiscard]] SpeedKernel speed_kernel(int degree, bool rational) noexcept;

// The variants (defined in span_simd*.cpp; nullptr outside degrees 2…5 and orders 0…3).
RunKernel run_kernel_baseline(int degree, bool rational, int order) noexcept;
RunKernel run_kernel_avx2(int degree, bool rational, int order) noexcept;
RunKernel run_kernel_avx512(int degree, bool rational, int order) noexcept;
SpeedKernel speed_kernel_baseline(int degree, bool rational) noexcept;
SpeedKernel speed_kernel_avx2(int degree, bool rational) noexcept;
SpeedKernel speed_kernel_avx512(int degree, bool rational) noexcept;

}  // namespace hula::nurbs::detail
