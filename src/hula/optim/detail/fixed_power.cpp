// SPDX-License-Identifier: MIT
#include "hula/optim/detail/fixed_power.hpp"

namespace hula::optim::detail {

FixedPower::FixedPower(double p) : p_(p), tabled_(p != 0.0 && p >= -1.0 && p <= 1.0) {
  if (!tabled_) return;
  for (int i = 0; i < kExponents; ++i)
    scale_[static_cast<std::size_t>(i)] = std::pow(std::ldexp(1.0, kMinExponent + i), p);
  for (int j = 0; j < kBins; ++j) {
    const auto u = static_cast<std::size_t>(j);
    centre_[u] = 0.5 + (j + 0.5) / (2 * kBins);  // exact: 8 significant bits
    inv_centre_[u] = 1.0 / centre_[u];
    bin_[u] = std::pow(centre_[u], p);
  }
  c_[0] = 1.0;
  for (int i = 1; i <= kDegree; ++i) {
    const auto u = static_cast<std::size_t>(i);
    c_[u] = c_[u - 1] * (p - (i - 1)) / i;
  }
}

const FixedPower& fixed_power(double p) {
  // Four slots, replaced round robin: SBX uses 1/e1 and -1/e1, mutation its own 1/e1.
  thread_local std::array<FixedPower, 4> slots;
  thread_local std::size_t next = 0;
  for (const FixedPower& s : slots) {
    if (s.exponent() == p) return s;
  }
  FixedPower& slot = slots[next];
  next = (next + 1) % slots.size();
  slot = FixedPower(p);
  return slot;
}

}  // namespace hula::optim::detail
