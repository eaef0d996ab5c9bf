// SPDX-License-Identifier: MIT
// The instruction-set detection (hula/core/simd.hpp) against the kernel's own view: Linux lists avx2 and
// avx512f among a CPU's flags in /proc/cpuinfo only when the CPU has them and the OS saves their registers
// (the kernel clears a feature whose register state XSAVE does not enable), the two conditions detect() checks.
#include "hula/core/simd.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace {

// The words of the first "flags" line of /proc/cpuinfo, each with a space on both sides; empty if unreadable.
std::string cpuinfo_flags() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.starts_with("flags")) return " " + line.substr(line.find(':') + 1) + " ";
  return {};
}

// checks: the widest supported level is the one /proc/cpuinfo's flags give (avx512f, else avx2, else the baseline)
TEST(Simd, SupportedLevelIsTheOneTheKernelReports) {
#if !defined(__x86_64__)
  GTEST_SKIP() << "the wide levels exist on x86-64 only";
#endif
  const std::string flags = cpuinfo_flags();
  if (flags.empty()) GTEST_SKIP() << "no /proc/cpuinfo";
  const hula::SimdLevel expected = flags.find(" avx512f ") != std::string::npos ? hula::SimdLevel::Avx512
                                   : flags.find(" avx2 ") != std::string::npos  ? hula::SimdLevel::Avx2
                                                                                : hula::SimdLevel::Baseline;
  EXPECT_EQ(hula::simd_level_name(hula::supported_simd_level()), hula::simd_level_name(expected)) << flags;
}

}  // namespace
