// SPDX-License-Identifier: MIT
#include "hula/optim/encoding.hpp"

#include <algorithm>
#include <cmath>

namespace hula::optim {

BinaryEncoding::BinaryEncoding(std::span<const Variable> variables) {
  for (std::size_t i = 0; i < variables.size(); ++i) {
    const Variable& v = variables[i];
    const std::size_t b = bits_for(v, i);
    bits_.push_back(b);
    lower_.push_back(v.lower);
    upper_.push_back(v.upper);
    step_.push_back((v.upper - v.lower) / (std::ldexp(1.0, static_cast<int>(b)) - 1.0));
    length_ += b;
  }
}

void BinaryEncoding::decode(std::span<const std::uint8_t> chromosome, std::span<double> variables) const noexcept {
  std::size_t pos = 0;
  for (std::size_t i = 0; i < bits_.size(); ++i) {
    std::uint64_t k = 0;
    for (std::size_t b = 0; b < bits_[i]; ++b) k = (k << 1) | (chromosome[pos + b] & 1U);
    pos += bits_[i];
    // k < 2^52 is exact in a double; the last level maps exactly to upper.
    const double levels = std::ldexp(1.0, static_cast<int>(bits_[i])) - 1.0;
    const double kd = static_cast<double>(k);
    variables[i] = kd == levels ? upper_[i] : lower_[i] + (upper_[i] - lower_[i]) * (kd / levels);
  }
}

std::vector<std::uint8_t> BinaryEncoding::encode(std::span<const double> variables) const {
  std::vector<std::uint8_t> out(length_, 0);
  std::size_t pos = 0;
  for (std::size_t i = 0; i < bits_.size(); ++i) {
    const double levels = std::ldexp(1.0, static_cast<int>(bits_[i])) - 1.0;
    const double t = upper_[i] > lower_[i] ? (variables[i] - lower_[i]) / (upper_[i] - lower_[i]) : 0.0;
    const auto k = static_cast<std::uint64_t>(std::clamp(std::round(t * levels), 0.0, levels));
    for (std::size_t b = 0; b < bits_[i]; ++b) {
      out[pos + b] = static_cast<std::uint8_t>((k >> (bits_[i] - 1 - b)) & 1U);
    }
    pos += bits_[i];
  }
  return out;
}

}  // namespace hula::optim
