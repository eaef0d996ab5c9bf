// SPDX-License-Identifier: MIT
// The span kernels of NurbsCurve's cache: derivatives 0…K of one cached polynomial piece at
// local parameters x, for a compile-time degree P, derivative order K and rationality R, written once
// over a lane type V that is either `double` (one point: the scalar path) or a GCC/Clang vector of
// doubles (several points of one span at once: the SIMD path).
//
// Every lane performs exactly the operations of the scalar path in the same order (no fused multiply-add:
// the translation units that include this file are compiled with -ffp-contract=off), so a point gets
// bit-for-bit the same value whichever path or instruction set evaluates it.
//
// This file is included by nurbs_curve.cpp and by one translation unit per instruction set
// (span_simd_*.cpp, compiled with -mavx2 / -mavx512f), each inside its own namespace named by
// HULA_SPAN_ISA, and it includes nothing with out-of-line inline functions: code compiled for a wider
// instruction set can then never be picked by the linker for a caller that runs on a narrower one.
//
// Notation (The NURBS Book): a_j = coefficient j (4 lanes x, y, z, w) of the homogeneous piece in
// x = (t − mid) / half; d[k] = A^(k)(x) / k! by repeated synthetic division (Horner), scaled by
// k! half^−k; rational derivatives by eq. 4.8, C^(k) = (A^(k) − Σ_{i=1..k} binom(k, i) w^(i) C^(k−i)) / w.
#ifndef HULA_SPAN_ISA
#error "define HULA_SPAN_ISA (the instruction-set namespace) before including span_eval.hpp"
#endif

#include <cstddef>

#include "hula/core/simd_lanes.hpp"
#if defined(__SSE2__)
#include <immintrin.h>  // movemask (static inline intrinsics: nothing with external linkage)
#endif

namespace hula::nurbs::detail::HULA_SPAN_ISA {

// s in every lane. s − 0 is s for every double, −0 and NaN included (s + 0 would turn −0 into +0), so the
// lanes start from the very values the scalar path uses.
template <class V>
inline V splat(double s) {
  if constexpr (sizeof(V) == sizeof(double)) {
    return s;
  } else {
    return s - V{};
  }
}

// True when every lane of t lies strictly inside (lo, hi) (false for NaN lanes).
template <class V>
inline bool all_inside(V t, double lo, double hi) {
  const auto inside = (t > lo) & (t < hi);  // lanes: −1 inside, 0 outside or NaN
#if defined(__AVX512F__)
  if constexpr (sizeof(V) == 64) return _mm512_cmpeq_epi64_mask(__m512i(inside), _mm512_set1_epi64(-1)) == 0xFF;
#endif
#if defined(__AVX__)
  if constexpr (sizeof(V) == 32) return _mm256_movemask_pd(__m256d(inside)) == 0xF;
#endif
#if defined(__SSE2__)
  if constexpr (sizeof(V) == 16) return _mm_movemask_pd(__m128d(inside)) == 0x3;
#endif
  long long all = -1;
  for (std::size_t l = 0; l < sizeof(V) / sizeof(double); ++l) all &= inside[l];
  return all != 0;
}

/// Derivatives 0…K (K ≥ 0) at local x of the piece with coefficients `a` ((P + 1) × 4 doubles) and
/// scale = 1 / half, into o[k][c] (c = 0, 1, 2). Orders above P are zero (non-rational) or follow from
/// the quotient rule (rational).
template <int P, bool R, int K, class V>
inline void eval_piece(const double* a, V x, double scale, V (*o)[3]) {
  // Lanes per coefficient. One point at a time (V = double) uses all four even when not rational, for
  // the derivatives: pairs of doubles vectorise, three do not (GCC's SLP then spills and reloads across
  // a store-forwarding boundary, 2.4 times slower on D3).
  constexpr int C = R || (sizeof(V) == sizeof(double) && K > 0) ? 4 : 3;
  constexpr int KK = K < P ? K : P;
  if constexpr (K == 0) {
    V acc[C];
    for (int c = 0; c < C; ++c) acc[c] = splat<V>(a[P * 4 + c]);
    for (int j = P - 1; j >= 0; --j)
      for (int c = 0; c < C; ++c) acc[c] = acc[c] * x + a[j * 4 + c];
    if constexpr (R) {
      const V inv = 1.0 / acc[3];
      for (int c = 0; c < 3; ++c) o[0][c] = acc[c] * inv;
    } else {
      for (int c = 0; c < 3; ++c) o[0][c] = acc[c];
    }
    return;
  } else {
    V d[KK + 1][C];
    for (int k = 1; k <= KK; ++k)
      for (int c = 0; c < C; ++c) d[k][c] = splat<V>(0.0);
    for (int c = 0; c < C; ++c) d[0][c] = splat<V>(a[P * 4 + c]);
    for (int j = P - 1; j >= 0; --j) {
      for (int k = (P - j < KK ? P - j : KK); k >= 1; --k)
        for (int c = 0; c < C; ++c) d[k][c] = d[k][c] * x + d[k - 1][c];
      for (int c = 0; c < C; ++c) d[0][c] = d[0][c] * x + a[j * 4 + c];
    }
    double f = 1.0;
    for (int k = 1; k <= KK; ++k) {
      f *= k * scale;
      for (int c = 0; c < C; ++c) d[k][c] *= f;
    }
    if constexpr (!R) {
      for (int k = 0; k <= KK; ++k)
        for (int c = 0; c < 3; ++c) o[k][c] = d[k][c];
      for (int k = KK + 1; k <= K; ++k)
        for (int c = 0; c < 3; ++c) o[k][c] = splat<V>(0.0);
    } else {
      const V inv_w = 1.0 / d[0][3];
      for (int c = 0; c < 3; ++c) o[0][c] = d[0][c] * inv_w;
      for (int k = 1; k <= K; ++k) {
        V v[3];
        for (int c = 0; c < 3; ++c) v[c] = k <= KK ? d[k][c] : splat<V>(0.0);
        double binom = 1.0;
        const int imax = k < KK ? k : KK;
        for (int i = 1; i <= imax; ++i) {
          binom = binom * (k - i + 1) / i;
          const V bw = binom * d[i][3];
          for (int c = 0; c < 3; ++c) v[c] -= bw * o[k - i][c];
        }
        for (int c = 0; c < 3; ++c) o[k][c] = v[c] * inv_w;
      }
    }
  }
}

template <class V>
inline void store(double* p, V v) {
  __builtin_memcpy(p, &v, sizeof v);
}

// 4 × 4 transpose: the four vectors' lane l, in order, land at p + l * stride (4 points, 4 values each).
template <class V4>
inline void store_transposed4(V4 a, V4 b, V4 c, V4 d, double* p, std::size_t stride) {
  const V4 t0 = __builtin_shufflevector(a, b, 0, 4, 2, 6);
  const V4 t1 = __builtin_shufflevector(a, b, 1, 5, 3, 7);
  const V4 t2 = __builtin_shufflevector(c, d, 0, 4, 2, 6);
  const V4 t3 = __builtin_shufflevector(c, d, 1, 5, 3, 7);
  store(p, V4(__builtin_shufflevector(t0, t2, 0, 1, 4, 5)));
  store(p + stride, V4(__builtin_shufflevector(t1, t3, 0, 1, 4, 5)));
  store(p + 2 * stride, V4(__builtin_shufflevector(t0, t2, 2, 3, 6, 7)));
  store(p + 3 * stride, V4(__builtin_shufflevector(t1, t3, 2, 3, 6, 7)));
}

// Four points of (K + 1) vectors each, from lanes to consecutive Vec3s (point-major, as NurbsCurve's
// output): transposes in registers where the shape allows, lane by lane otherwise.
template <int K, class V4>
inline void store_points4(V4 (*o)[3], double* p) {
  constexpr std::size_t stride = 3 * (K + 1);
  if constexpr (K == 0) {
    const V4 x = o[0][0], y = o[0][1], z = o[0][2];
    const V4 xy = __builtin_shufflevector(x, y, 0, 4, 1, 5);         // x0 y0 x1 y1
    const V4 yz = __builtin_shufflevector(y, z, 1, 5, 2, 6);         // y1 z1 y2 z2
    const V4 xy23 = __builtin_shufflevector(x, y, 2, 6, 3, 7);       // x2 y2 x3 y3
    store(p, V4(__builtin_shufflevector(xy, z, 0, 1, 4, 2)));        // x0 y0 z0 x1
    store(p + 4, V4(__builtin_shufflevector(yz, x, 0, 1, 6, 2)));    // y1 z1 x2 y2
    store(p + 8, V4(__builtin_shufflevector(z, xy23, 2, 6, 7, 3)));  // z2 x3 y3 z3
  } else if constexpr (K == 3) {
    // Values 0…11 of a point: (k, c) = (0,0) (0,1) (0,2) (1,0) | (1,1) (1,2) (2,0) (2,1) | (2,2) (3,0) (3,1) (3,2).
    store_transposed4(o[0][0], o[0][1], o[0][2], o[1][0], p, stride);
    store_transposed4(o[1][1], o[1][2], o[2][0], o[2][1], p + 4, stride);
    store_transposed4(o[2][2], o[3][0], o[3][1], o[3][2], p + 8, stride);
  } else {
    for (int l = 0; l < 4; ++l)
      for (int k = 0; k <= K; ++k)
        for (int c = 0; c < 3; ++c) p[l * stride + 3 * k + c] = o[k][c][l];
  }
}

// W points of (K + 1) vectors each, from lanes to consecutive Vec3s.
template <int W, int K, class V>
inline void store_points(V (*o)[3], double* p) {
  constexpr std::size_t stride = 3 * (K + 1);
  if constexpr (W == 2) {
    // Output element e of the two points comes from value e % (3 (K + 1)) of lane e / (3 (K + 1)): pairs
    // of consecutive elements are one two-source shuffle each.
    const V* v = &o[0][0];
    constexpr int n = static_cast<int>(stride);
    for (int e = 0; e < 2 * n; e += 2) {
      const int m0 = e % n, m1 = (e + 1) % n;
      if (e + 1 < n)
        store(p + e, V(__builtin_shufflevector(v[m0], v[m1], 0, 2)));
      else if (e >= n)
        store(p + e, V(__builtin_shufflevector(v[m0], v[m1], 1, 3)));
      else
        store(p + e, V(__builtin_shufflevector(v[m0], v[m1], 0, 3)));
    }
  } else if constexpr (W == 4) {
    store_points4<K>(o, p);
  } else if constexpr (W == 8) {
    using V4 = simd_lanes_t<4>;
    V4 lo[K + 1][3], hi[K + 1][3];
    for (int k = 0; k <= K; ++k)
      for (int c = 0; c < 3; ++c) {
        lo[k][c] = __builtin_shufflevector(o[k][c], o[k][c], 0, 1, 2, 3);
        hi[k][c] = __builtin_shufflevector(o[k][c], o[k][c], 4, 5, 6, 7);
      }
    store_points4<K>(lo, p);
    store_points4<K>(hi, p + 4 * stride);
  }
}

/// Evaluates W points at a time from ts[0] on while every point of the next W lies strictly inside
/// (lo, hi), the open span (no domain policy, no breakpoint snapping needed there), and returns how many
/// it evaluated (a multiple of W); the caller takes the rest point by point. out receives (K + 1) vectors
/// of 3 doubles per point, point i at out + 3 (K + 1) i.
template <int W, int P, bool R, int K>
std::size_t eval_run(const double* a, double mid, double scale, double lo, double hi, const double* ts, std::size_t n,
                     double* out) {
  using V = simd_lanes_t<W>;
  constexpr std::size_t stride = 3 * (K + 1);
  std::size_t i = 0;
  for (; i + W <= n; i += W) {
    V t;
    __builtin_memcpy(&t, ts + i, sizeof t);
    if (!all_inside(t, lo, hi)) break;
    const V x = (t - mid) * scale;
    V o[K + 1][3];
    eval_piece<P, R, K>(a, x, scale, o);
    store_points<W, K>(o, out + i * stride);
  }
  return i;
}

// √s in every lane (correctly rounded, as std::sqrt).
template <class V>
inline V lane_sqrt(V s) {
#if defined(__AVX512F__)
  // Every lane computed (mask all ones); _mm512_sqrt_pd's undefined pass-through trips GCC 12's
  // -Wmaybe-uninitialized.
  if constexpr (sizeof(V) == 64) return V(_mm512_mask_sqrt_pd(__m512d(s), __mmask8(0xFF), __m512d(s)));
#endif
#if defined(__AVX__)
  if constexpr (sizeof(V) == 32) return V(_mm256_sqrt_pd(__m256d(s)));
#endif
#if defined(__SSE2__)
  if constexpr (sizeof(V) == 16) return V(_mm_sqrt_pd(__m128d(s)));
#endif
  V r = s;
  for (std::size_t l = 0; l < sizeof(V) / sizeof(double); ++l) r[l] = __builtin_sqrt(s[l]);
  return r;
}

/// The speed |C'(t)| at n parameters (n a multiple of W), every one strictly inside the span: the first
/// derivative as eval_run gives it, and √(x² + y² + z²) as norm() computes it where |C'|² lies in
/// (1e-290, 1e290). Returns false when some point's |C'|² does not (norm would scale it; NaN and ∞
/// included): the caller then evaluates them the general way. out receives n doubles.
template <int W, int P, bool R>
bool speed_run(const double* a, double mid, double scale, const double* ts, std::size_t n, double* out) {
  using V = simd_lanes_t<W>;
  bool plain = true;
  for (std::size_t i = 0; i + W <= n; i += W) {
    V t;
    __builtin_memcpy(&t, ts + i, sizeof t);
    const V x = (t - mid) * scale;
    V o[2][3];
    eval_piece<P, R, 1>(a, x, scale, o);
    const V s = o[1][0] * o[1][0] + o[1][1] * o[1][1] + o[1][2] * o[1][2];
    plain = all_inside(s, 1e-290, 1e290) & plain;
    store(out + i, lane_sqrt(s));
  }
  return plain;
}

/// The speed kernel of one instruction set (W ≥ 2): speed_run for (degree, rational), or nullptr outside
/// degrees 2…5.
using SpeedKernel = bool (*)(const double*, double, double, const double*, std::size_t, double*);

template <int W>
SpeedKernel speed_kernel(int degree, bool rational) {
  switch (degree) {
    case 2:
      return rational ? &speed_run<W, 2, true> : &speed_run<W, 2, false>;
    case 3:
      return rational ? &speed_run<W, 3, true> : &speed_run<W, 3, false>;
    case 4:
      return rational ? &speed_run<W, 4, true> : &speed_run<W, 4, false>;
    case 5:
      return rational ? &speed_run<W, 5, true> : &speed_run<W, 5, false>;
    default:
      return nullptr;
  }
}

/// The run kernel of one instruction set: eval_run for (degree, rational, order), or nullptr outside
/// degrees 2…5 and orders 0…3 (W ≥ 2).
using RunKernel = std::size_t (*)(const double*, double, double, double, double, const double*, std::size_t, double*);

template <int W, bool R, int K>
constexpr RunKernel run_for_degree(int degree) {
  switch (degree) {
    case 2:
      return &eval_run<W, 2, R, K>;
    case 3:
      return &eval_run<W, 3, R, K>;
    case 4:
      return &eval_run<W, 4, R, K>;
    case 5:
      return &eval_run<W, 5, R, K>;
    default:
      return nullptr;
  }
}

template <int W>
RunKernel run_kernel(int degree, bool rational, int order) {
  switch (order) {
    case 0:
      return rational ? run_for_degree<W, true, 0>(degree) : run_for_degree<W, false, 0>(degree);
    case 1:
      return rational ? run_for_degree<W, true, 1>(degree) : run_for_degree<W, false, 1>(degree);
    case 2:
      return rational ? run_for_degree<W, true, 2>(degree) : run_for_degree<W, false, 2>(degree);
    case 3:
      return rational ? run_for_degree<W, true, 3>(degree) : run_for_degree<W, false, 3>(degree);
    default:
      return nullptr;
  }
}

}  // namespace hula::nurbs::detail::HULA_SPAN_ISA
