// SPDX-License-Identifier: MIT
// The portable run kernels (two doubles per vector: SSE2 on x86-64) and the choice of instruction set
// for NurbsCurve's batch evaluation. The wider variants live in span_simd_avx2.cpp and
// span_simd_avx512.cpp (x86-64 only), each compiled for its own instruction set.
#include "hula/nurbs/detail/span_simd.hpp"

#include <atomic>
#include <cstdlib>
#include <string_view>

#define HULA_SPAN_ISA baseline
#include "hula/nurbs/detail/span_eval.hpp"
#undef HULA_SPAN_ISA

namespace hula::nurbs::detail {

namespace {

SimdLevel detect() noexcept {
#if defined(HULA_SIMD_X86) && (defined(__GNUC__) || defined(__clang__))
  __builtin_cpu_init();
  // __builtin_cpu_supports also checks that the OS saves the wide registers (XGETBV).
  if (__builtin_cpu_supports("avx512f")) return SimdLevel::Avx512;
  if (__builtin_cpu_supports("avx2")) return SimdLevel::Avx2;
#endif
  return SimdLevel::Baseline;
}

// HULA_SIMD caps the level (unknown values are ignored).
SimdLevel from_environment(SimdLevel supported) noexcept {
  const char* v = std::getenv("HULA_SIMD");
  if (v == nullptr) return supported;
  const std::string_view s(v);
  SimdLevel cap = supported;
  if (s == "scalar") cap = SimdLevel::Scalar;
  if (s == "baseline") cap = SimdLevel::Baseline;
  if (s == "avx2") cap = SimdLevel::Avx2;
  if (s == "avx512") cap = SimdLevel::Avx512;
  return cap < supported ? cap : supported;
}

std::atomic<SimdLevel>& current() noexcept {
  static std::atomic<SimdLevel> level{from_environment(supported_simd_level())};
  return level;
}

}  // namespace

SimdLevel supported_simd_level() noexcept {
  static const SimdLevel level = detect();
  return level;
}

SimdLevel simd_level() noexcept { return current().load(std::memory_order_relaxed); }

SimdLevel set_simd_level(SimdLevel level) noexcept {
  const SimdLevel supported = supported_simd_level();
  return current().exchange(level < supported ? level : supported, std::memory_order_relaxed);
}

std::string_view simd_level_name(SimdLevel level) noexcept {
  switch (level) {
    case SimdLevel::Scalar:
      return "scalar";
    case SimdLevel::Baseline:
      return "baseline";
    case SimdLevel::Avx2:
      return "avx2";
    case SimdLevel::Avx512:
      return "avx512";
  }
  return "scalar";
}

RunKernel run_kernel_baseline(int degree, bool rational, int order) noexcept {
  return baseline::run_kernel<2>(degree, rational, order);
}

#if !defined(HULA_SIMD_X86)
RunKernel run_kernel_avx2(int, bool, int) noexcept { return nullptr; }
RunKernel run_kernel_avx512(int, bool, int) noexcept { return nullptr; }
#endif

RunKernel run_kernel(int degree, bool rational, int order) noexcept {
  switch (simd_level()) {
    case SimdLevel::Scalar:
      return nullptr;
    case SimdLevel::Baseline:
      return run_kernel_baseline(degree, rational, order);
    case SimdLevel::Avx2:
      return run_kernel_avx2(degree, rational, order);
    case SimdLevel::Avx512:
      return run_kernel_avx512(degree, rational, order);
  }
  return nullptr;
}

}  // namespace hula::nurbs::detail
