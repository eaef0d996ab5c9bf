// SPDX-License-Identifier: MIT
// The lane types of the vectorised kernels (nurbs' span kernels, the studies' profile kernel): W
// doubles as one GCC/Clang vector, so a kernel is written once over a lane type and instantiated for
// one point (W = 1, plain double) and for 2, 4 or 8 points at once (SSE2, AVX2, AVX-512F registers).
//
// Types only, on purpose: the kernels' translation units are compiled for different instruction sets
// (hula/core/simd.hpp), and a header they share must hold no function with external linkage, or the
// linker could pick a copy compiled for a wider set for a caller that runs on a narrower one.
#pragma once

namespace hula {

/// W doubles as one GCC/Clang vector; W = 1 is plain double.
template <int W>
struct SimdLanes;
template <>
struct SimdLanes<1> {
  using type = double;
};
template <>
struct SimdLanes<2> {
  using type = double __attribute__((vector_size(16)));
};
template <>
struct SimdLanes<4> {
  using type = double __attribute__((vector_size(32)));
};
template <>
struct SimdLanes<8> {
  using type = double __attribute__((vector_size(64)));
};

/// The lane type of W doubles (double for W = 1).
template <int W>
using simd_lanes_t = typename SimdLanes<W>::type;

}  // namespace hula
