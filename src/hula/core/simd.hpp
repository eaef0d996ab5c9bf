// SPDX-License-Identifier: MIT
// The instruction set the vectorised kernels run with: the portable baseline (two doubles per
// vector: SSE2 on x86-64) that every build has, and on x86-64 AVX2 (four) and AVX-512F (eight) when the
// CPU and the OS support them, picked once at run time. The default build stays portable: only the
// kernels' own translation units are compiled for the wider sets (nurbs/detail/span_simd*.cpp,
// studies/detail/profile_kernel*.cpp), and every variant gives bit-identical results (no fused
// multiply-add, the same operations per lane), so the choice changes speed only.
//
// HULA_SIMD=scalar|baseline|avx2|avx512 in the environment caps the level (benchmarks comparing the
// variants, tests); set_simd_level does the same from code.
#pragma once

#include <string_view>

namespace hula {

/// Instruction sets of the vectorised kernels, narrowest first. Scalar: one point at a time.
enum class SimdLevel { Scalar, Baseline, Avx2, Avx512 };

/// The level in use: the widest supported, capped by HULA_SIMD and set_simd_level.
[[nodiscard]] SimdLevel simd_level() noexcept;
/// The widest level this CPU and OS support (ignores HULA_SIMD).
[[nodiscard]] SimdLevel supported_simd_level() noexcept;
/// Uses `level` (capped at the supported one) from now on, for every thread; returns the previous level.
SimdLevel set_simd_level(SimdLevel level) noexcept;
/// "scalar", "baseline", "avx2", "avx512".
[[nodiscard]] std::string_view simd_level_name(SimdLevel level) noexcept;

}  // namespace hula
