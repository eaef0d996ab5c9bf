// SPDX-License-Identifier: MIT
// Banded linear solver with partial pivoting (the scheme of LAPACK dgbsv) for
// the O(N) systems of spline interpolation, collocation and approximation:
// A has kl sub-diagonals and ku super-diagonals, and the right-hand side has
// several columns (x, y, z, and w for rational curves).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace hula {

/// A square banded matrix in compact storage, with room for the fill-in of
/// partial pivoting. Entry (i, j) is addressable when -kl ≤ j - i ≤ ku.
class BandedMatrix {
 public:
  /// @param n order of the matrix; @param kl, ku number of sub/super-diagonals.
  BandedMatrix(std::size_t n, std::size_t kl, std::size_t ku);

  [[nodiscard]] std::size_t size() const noexcept { return n_; }
  /// Entry (i, j); requires -kl ≤ j - i ≤ ku.
  [[nodiscard]] double& at(std::size_t i, std::size_t j);
  [[nodiscard]] double at(std::size_t i, std::size_t j) const;

  /// Solves A X = B in place: `rhs` holds `columns` right-hand sides stored
  /// row-major (rhs[i * columns + c]) and receives the solution. Destroys A.
  /// Cost O(n · kl · (kl + ku + columns)).
  /// @returns false when A is singular to working precision (a zero or
  /// denormal pivot relative to the row scale); rhs is then unspecified.
  [[nodiscard]] bool solve(std::span<double> rhs, std::size_t columns);

 private:
  std::size_t n_, kl_, ku_, width_;
  std::vector<double> data_;  // row-major band, width_ = 2*kl + ku + 1 columns
};

}  // namespace hula
