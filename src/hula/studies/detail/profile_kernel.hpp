// SPDX-License-Identifier: MIT
// The sample kernel of SplineProfileSampler (the GA fitness): κ, and τ on request, of a
// cubic spline at many sorted parameters, W samples per vector, written once over a lane type that is
// `double` (one sample: the tail) or a GCC/Clang vector of doubles. Each lane performs exactly the
// operations of the scalar sampler in the same order (no fused multiply-add: the including translation
// units are compiled with -ffp-contract=off), so every instruction set gives the same doubles.
//
// Included by profile_kernel.cpp (baseline) and profile_kernel_avx2.cpp / _avx512.cpp (compiled with
// -mavx2 / -mavx512f), each inside its own namespace HULA_PROFILE_ISA; it includes nothing with
// out-of-line inline functions, so code for a wider instruction set can never be picked by the linker
// for a narrower caller.
//
// Notation (curvature_match.hpp): on span k, with w = u − t_k and per coordinate the coefficients
// (b, c, d) of C(t) = a + b w + c w² + d w³: C' = b + w (2c + 3d w), C'' = 2c + 6d w, C''' = 6d;
// X = C' × C'', κ = |X| / |C'|³, τ = (X · C''') / |X|² (NaN where |X| ≤ 1e-12 |C'|³, 0 in the plane).
#ifndef HULA_PROFILE_ISA
#error "define HULA_PROFILE_ISA (the instruction-set namespace) before including profile_kernel.hpp"
#endif

#include <cstddef>

#include "hula/core/simd_lanes.hpp"
#if defined(__SSE2__)
#include <immintrin.h>  // square roots (static inline intrinsics: nothing with external linkage)
#endif

namespace hula::studies::detail::HULA_PROFILE_ISA {

// The lane mask type of V: what a comparison of two V gives (bool for double).
template <class V>
using Mask = decltype(V{} < V{});

// s in every lane (s − 0 is s for every double, −0 and NaN included).
template <class V>
inline V splat(double s) {
  if constexpr (sizeof(V) == sizeof(double)) {
    return s;
  } else {
    return s - V{};
  }
}

// Correctly rounded square root per lane (the same as std::sqrt).
template <class V>
inline V root(V v) {
  if constexpr (sizeof(V) == sizeof(double)) {
    return __builtin_sqrt(v);
  } else {
#if defined(__AVX512F__)
    // The masked form with every lane selected: GCC 12's _mm512_sqrt_pd passes an undefined pass-through
    // operand, which -Wmaybe-uninitialized reports.
    if constexpr (sizeof(V) == 64) return V(_mm512_mask_sqrt_pd(__m512d(v), 0xFF, __m512d(v)));
#endif
#if defined(__AVX__)
    if constexpr (sizeof(V) == 32) return V(_mm256_sqrt_pd(__m256d(v)));
#endif
#if defined(__SSE2__)
    if constexpr (sizeof(V) == 16) return V(_mm_sqrt_pd(__m128d(v)));
#endif
    V r;
    for (std::size_t l = 0; l < sizeof(V) / sizeof(double); ++l) r[l] = __builtin_sqrt(v[l]);
    return r;
  }
}

// |v| per lane (clears the sign bit).
template <class V>
inline V magnitude(V v) {
  if constexpr (sizeof(V) == sizeof(double)) {
    return __builtin_fabs(v);
  } else {
    using I = Mask<V>;
    return V(I(v) & (I{} + static_cast<decltype(+I{}[0])>(0x7fffffffffffffffLL)));
  }
}

// a where m, else b, per lane.
template <class V>
inline V select(Mask<V> m, V a, V b) {
  return m ? a : b;
}

// The samples u[0 .. lanes of V) (see profile_samples): coefficients q (3 D values) and span start tk
// of type C, a double shared by every lane or a V with one span per lane. Returns κ − κ per lane (0 for
// finite κ, else NaN).
template <class V, int D, bool T, class C>
__attribute__((always_inline)) inline V profile_lanes(const C* q, C tk, const double* u, double* kappa, double* tau) {
  constexpr double kTiny = 0x1p-1022;       // smallest normal double
  constexpr double kTorsionCutoff = 1e-12;  // curvature_match.cpp's τ cutoff
  V uu;
  __builtin_memcpy(&uu, u, sizeof uu);
  const V w = uu - tk;
  V d1[3], d2[3];
  C d3[3];
  for (int c = 0; c < D; ++c) {
    const C* s = q + 3 * c;
    d1[c] = s[0] + w * (2.0 * s[1] + 3.0 * s[2] * w);
    d2[c] = 2.0 * s[1] + 6.0 * s[2] * w;
    d3[c] = 6.0 * s[2];
  }
  const V cz = d1[0] * d2[1] - d1[1] * d2[0];
  V cross2, speed2, cross_norm, cx{}, cy{};
  if constexpr (D == 2) {
    // The scalar sampler's 3-D sums with zero z: cross2 = (+0) + (+0) + cz², speed2 = x'² + y'² + (+0),
    // the same doubles; and √(cz²) = |cz| exactly while cz² is a normal number (a correctly rounded
    // square is within half an ulp of the exact one), which saves a square root.
    cross2 = cz * cz;
    speed2 = d1[0] * d1[0] + d1[1] * d1[1];
    cross_norm = select<V>(cross2 >= kTiny, magnitude(cz), root(cross2));
  } else {
    cx = d1[1] * d2[2] - d1[2] * d2[1];
    cy = d1[2] * d2[0] - d1[0] * d2[2];
    cross2 = cx * cx + cy * cy + cz * cz;
    speed2 = d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2];
    cross_norm = root(cross2);
  }
  const V speed3 = speed2 * root(speed2);
  const V k = cross_norm / speed3;
  __builtin_memcpy(kappa, &k, sizeof k);
  if constexpr (T) {
    V t;
    if constexpr (D == 2) {
      t = splat<V>(0.0);
    } else {
      // Undefined lanes divide by 1 instead of a vanishing |X|², so no lane raises a division by zero
      // that the scalar sampler would not (Debug tests trap FE_DIVBYZERO).
      const Mask<V> undefined = cross_norm <= kTorsionCutoff * speed3;
      const V safe = select<V>(undefined, splat<V>(1.0), cross2);
      t = select<V>(undefined, splat<V>(__builtin_nan("")), (cx * d3[0] + cy * d3[1] + cz * d3[2]) / safe);
    }
    __builtin_memcpy(tau, &t, sizeof t);
  }
  return k - k;
}

// W samples starting at u whose spans (span[l]) differ: each lane gathers its span's coefficients.
template <class V, int W, int D, bool T>
inline V profile_mixed(const double* coef, const double* tstart, const unsigned* span, const double* u, double* kappa,
                       double* tau) {
  V q[3 * D] = {}, tk{};
  for (int l = 0; l < W; ++l) {
    const double* s = coef + 9 * span[l];
    for (int j = 0; j < 3 * D; ++j) q[j][l] = s[j];
    tk[l] = tstart[span[l]];
  }
  return profile_lanes<V, D, T, V>(q, tk, u, kappa, tau);
}

/// κ (and τ when T) at the m sorted parameters u, sample i in span span[i] (start tstart[span[i]],
/// coefficients coef + 9 span[i]: (b, c, d) of x, then y, then z), D = 2 or 3 coordinates, W samples per
/// vector (lanes of one vector may lie in different spans). Returns 0 when every κ is finite, else NaN
/// (a probe summed per lane, so no dependency chain runs through the samples).
template <int W, int D, bool T>
double profile_samples(const double* coef, const double* tstart, const unsigned* span, const double* u, std::size_t m,
                       double* kappa, double* tau) {
  std::size_t i = 0;
  double probe = 0.0;
  if constexpr (W > 1) {
    using V = simd_lanes_t<W>;
    V lanes{};
    for (; i + W <= m; i += W) {
      double* ti = T ? tau + i : nullptr;
      const unsigned s = span[i];
      if (s == span[i + W - 1]) {
        lanes += profile_lanes<V, D, T, double>(coef + 9 * s, tstart[s], u + i, kappa + i, ti);
      } else if (span[i + W - 1] == s + 1) {
        // Two spans (the common boundary): the first r lanes take span s, the rest span s + 1.
        int r = 1;
        while (span[i + static_cast<std::size_t>(r)] == s) ++r;
        V lane{};
        for (int l = 0; l < W; ++l) lane[l] = l;
        const Mask<V> first = lane < static_cast<double>(r);
        const double* a = coef + 9 * s;
        const double* b = a + 9;
        V q[3 * D] = {};
        for (int j = 0; j < 3 * D; ++j) q[j] = select<V>(first, splat<V>(a[j]), splat<V>(b[j]));
        const V tk = select<V>(first, splat<V>(tstart[s]), splat<V>(tstart[s + 1]));
        lanes += profile_lanes<V, D, T, V>(q, tk, u + i, kappa + i, ti);
      } else {
        lanes += profile_mixed<V, W, D, T>(coef, tstart, span + i, u + i, kappa + i, ti);
      }
    }
    for (int l = 0; l < W; ++l) probe += lanes[l];
    if (i < m) {
      // The last m − i samples in one vector, its other lanes repeating the last sample (a value the
      // scalar path computes too, so no lane can raise an exception the scalar path would not).
      const std::size_t r = m - i;
      double pu[W], pk[W], pt[W];
      unsigned ps[W];
      for (std::size_t l = 0; l < W; ++l) {
        const std::size_t from = l < r ? i + l : m - 1;
        pu[l] = u[from];
        ps[l] = span[from];
      }
      const V tail = profile_mixed<V, W, D, T>(coef, tstart, ps, pu, pk, pt);
      for (std::size_t l = 0; l < r; ++l) {
        kappa[i + l] = pk[l];
        if constexpr (T) tau[i + l] = pt[l];
        probe += tail[l];
      }
      i = m;
    }
  }
  for (; i < m; ++i) {
    const unsigned s = span[i];
    probe += profile_lanes<double, D, T, double>(coef + 9 * s, tstart[s], u + i, kappa + i, T ? tau + i : nullptr);
  }
  return probe;
}

/// The kernel of one instruction set for D coordinates, with or without τ.
using ProfileKernel = double (*)(const double*, const double*, const unsigned*, const double*, std::size_t, double*,
                                 double*);

template <int W>
ProfileKernel profile_kernel(int dimension, bool torsion) {
  if (dimension == 2) return torsion ? &profile_samples<W, 2, true> : &profile_samples<W, 2, false>;
  return torsion ? &profile_samples<W, 3, true> : &profile_samples<W, 3, false>;
}

}  // namespace hula::studies::detail::HULA_PROFILE_ISA
