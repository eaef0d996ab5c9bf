// SPDX-License-Identifier: MIT
// Runtime choice of the instruction set for NurbsCurve's batch evaluation (issue 27): the run kernels of
// detail/span_eval.hpp compiled for the portable baseline (two doubles per vector, SSE2 on x86-64) and,
// on x86-64, for AVX2 (four) and AVX-512F (eight), the widest the CPU and the OS support picked once.
// Every variant gives bit-identical results (span_eval.hpp), so the choice changes speed only.
// HULA_SIMD=scalar|baseline|avx2|avx512 in the environment caps the choice (benchmarks, tests).
#pragma once

#include <cstddef>
#include <string_view>

namespace hula::nurbs::detail {

/// Evaluates points of one span, several at a time, from ts[0] on while they lie strictly inside the
/// open span (lo, hi): coefficients of the span, its midpoint and 1 / half-length, the span's ends, n
/// parameters, out 3 (order + 1) doubles per point. Returns how many points it evaluated.
using RunKernel = std::size_t (*)(const double* coef, double mid, double scale, double lo, double hi, const double* ts,
                                  std::size_t n, double* out);

/// Instruction sets of the run kernels, narrowest first.
enum class SimdLevel { Scalar, Baseline, Avx2, Avx512 };

/// The level in use: the widest supported, capped by HULA_SIMD and set_simd_level.
[[nodiscard]] SimdLevel simd_level() noexcept;
/// The widest level this CPU supports (ignores HULA_SIMD).
[[nodiscard]] SimdLevel supported_simd_level() noexcept;
/// Uses `level` (capped at the supported one) from now on, for every thread; returns the previous level.
/// For tests and benchmarks that compare the variants.
SimdLevel set_simd_level(SimdLevel level) noexcept;
/// "scalar", "baseline", "avx2", "avx512".
[[nodiscard]] std::string_view simd_level_name(SimdLevel level) noexcept;

/// The run kernel for (degree, rational, order) at the current level; nullptr = evaluate point by point.
[[nodiscard]] RunKernel run_kernel(int degree, bool rational, int order) noexcept;

// The variants (defined in span_simd*.cpp; nullptr outside degrees 2…5 and orders 0…3).
RunKernel run_kernel_baseline(int degree, bool rational, int order) noexcept;
RunKernel run_kernel_avx2(int degree, bool rational, int order) noexcept;
RunKernel run_kernel_avx512(int degree, bool rational, int order) noexcept;

}  // namespace hula::nurbs::detail
