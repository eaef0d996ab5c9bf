// SPDX-License-Identifier: MIT
// The sample kernel of SplineProfileSampler for the instruction set in use (hula/core/simd.hpp); see
// profile_kernel.hpp for what it computes. Every variant gives the same doubles.
#pragma once

#include <cstddef>

namespace hula::studies::detail {

/// κ (and τ when `tau` is not null) at m sorted parameters u, sample i in span span[i]: span starts
/// tstart, coefficients coef + 9 span = (b, c, d) of x, then y, then z. Returns 0 when every κ is finite,
/// else NaN.
using ProfileKernel = double (*)(const double* coef, const double* tstart, const unsigned* span, const double* u,
                                 std::size_t m, double* kappa, double* tau);

/// The kernel for 2 or 3 coordinates, with or without τ, at hula::simd_level().
[[nodiscard]] ProfileKernel profile_kernel(int dimension, bool torsion) noexcept;

// The wide variants (profile_kernel_avx2.cpp, profile_kernel_avx512.cpp; x86-64).
ProfileKernel profile_kernel_avx2(int dimension, bool torsion) noexcept;
ProfileKernel profile_kernel_avx512(int dimension, bool torsion) noexcept;

}  // namespace hula::studies::detail
