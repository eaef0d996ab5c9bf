// SPDX-License-Identifier: MIT
// Binary coding of design variables (appendix 2 "Individual": "number of
// chromosome bits corresponding to each problem variable"): a variable with
// bounds [l, u] and precision p gets the smallest b with (u - l)/(2^b - 1) <= p,
// and the gene's unsigned integer k (most significant bit first) decodes to
// x = l + (u - l) k / (2^b - 1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "hula/optim/problem.hpp"

namespace hula::optim {

/// The bit layout of a chromosome for a problem's variables.
class BinaryEncoding {
 public:
  /// Builds the layout from every variable's bounds and precision.
  /// @throws hula::Error(Errc::InvalidOption) if a variable has precision 0
  ///   (not binary-coded) or needs more than 52 bits; the message names
  ///   "variables[i].precision" and its value.
  explicit BinaryEncoding(std::span<const Variable> variables);
  /// Total chromosome length in bits.
  [[nodiscard]] std::size_t length() const noexcept { return length_; }
  /// Bits of variable i.
  [[nodiscard]] std::size_t bits(std::size_t i) const noexcept { return bits_[i]; }
  /// Achieved resolution of variable i, (u - l) / (2^b - 1) <= precision.
  [[nodiscard]] double resolution(std::size_t i) const noexcept { return step_[i]; }
  /// Number of variables.
  [[nodiscard]] std::size_t dimension() const noexcept { return bits_.size(); }
  /// Decodes a chromosome into variable values inside the bounds.
  /// @param chromosome length() bits, one per byte (0 or 1), most significant first per gene.
  /// @param variables output, dimension() values (a caller buffer: decoding runs per individual).
  void decode(std::span<const std::uint8_t> chromosome, std::span<double> variables) const noexcept;
  /// Encodes values (rounded to the nearest level, clamped to the bounds).
  /// @param variables dimension() values.
  /// @returns length() bits.
  [[nodiscard]] std::vector<std::uint8_t> encode(std::span<const double> variables) const;

 private:
  std::vector<std::size_t> bits_;
  std::vector<double> lower_, upper_, step_;
  std::size_t length_ = 0;
};

}  // namespace hula::optim
