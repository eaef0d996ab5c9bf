// SPDX-License-Identifier: MIT
// Detection of the vector instruction sets (see simd.hpp).
#include "hula/core/simd.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <cpuid.h>
#endif

#include <atomic>
#include <cstdlib>
#include <string_view>

namespace hula {

namespace {

// The checks of GCC's __builtin_cpu_supports("avx512f") and ("avx2"): the CPU has the instructions (CPUID
// leaf 7) and the OS saves their registers (OSXSAVE, then XCR0's SSE and AVX state, and for AVX-512 the
// opmask and both ZMM states). Asked here, on first use, because __builtin_cpu_supports links libgcc's
// __cpu_indicator_init, a static initialiser every run of every program holding this code would pay for
// (CPUID traps in a VM: a few per cent of `hula --version`, docs/benchmarks.md).
SimdLevel detect() noexcept {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  if (__get_cpuid(1, &eax, &ebx, &ecx, &edx) == 0 || (ecx & bit_OSXSAVE) == 0) return SimdLevel::Baseline;
  unsigned xcr0 = 0, xcr0_high = 0;
  __asm__("xgetbv" : "=a"(xcr0), "=d"(xcr0_high) : "c"(0));
  constexpr unsigned kSseAvx = 0x2 | 0x4, kAvx512 = 0x20 | 0x40 | 0x80;
  if ((xcr0 & kSseAvx) != kSseAvx || __get_cpuid_count(7, 0, &eax, &ebx, &ecx, &edx) == 0) return SimdLevel::Baseline;
  if ((xcr0 & kAvx512) == kAvx512 && (ebx & bit_AVX512F) != 0) return SimdLevel::Avx512;
  if ((ebx & bit_AVX2) != 0) return SimdLevel::Avx2;
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

}  // namespace hula
