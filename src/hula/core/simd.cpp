// SPDX-License-Identifier: MIT
// Detection of the vector instruction sets (see simd.hpp).
#include "hula/core/simd.hpp"

#include <atomic>
#include <cstdlib>
#include <string_view>

namespace hula {

namespace {

SimdLevel detect() noexcept {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  __builtin_cpu_init();
  // __builtin_cpu_supports also requires the OS to save the wide registers (XGETBV).
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

}  // namespace hula
