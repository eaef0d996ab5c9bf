// SPDX-License-Identifier: MIT
// xoshiro256** and SplitMix64 as published by Blackman & Vigna (public domain
// reference algorithms), written from their descriptions.
#include "hula/core/rng.hpp"

#include <cmath>

namespace hula {
namespace {
std::uint64_t splitmix64(std::uint64_t& x) noexcept {
  std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
}  // namespace

Rng::Rng(std::uint64_t seed, std::uint64_t stream) noexcept {
  // Mix the stream index into the seed through a separate SplitMix64 pass so
  // that (seed, stream) pairs map to unrelated states.
  std::uint64_t x = seed;
  std::uint64_t mixed = splitmix64(x) ^ (stream * 0xd1b54a32d192ed03ULL);
  std::uint64_t y = mixed + stream;
  for (auto& word : s_) word = splitmix64(y);
  if ((s_[0] | s_[1] | s_[2] | s_[3]) == 0) s_[0] = 1;  // the all-zero state is a fixed point
}

double Rng::normal() noexcept {
  double u = 0.0, v = 0.0, s = 0.0;
  do {
    u = uniform(-1.0, 1.0);
    v = uniform(-1.0, 1.0);
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  return u * std::sqrt(-2.0 * std::log(s) / s);
}

}  // namespace hula
