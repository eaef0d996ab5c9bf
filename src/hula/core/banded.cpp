// SPDX-License-Identifier: MIT
// Gaussian elimination with partial pivoting on a band matrix. Row interchanges
// widen the upper band from ku to kl + ku (as in LAPACK dgbtrf), so the storage
// keeps kl extra super-diagonals. Row i is stored at offset (j - i + kl) so that
// fill-in up to column i + kl + ku fits.
#include "hula/core/banded.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hula/core/error.hpp"

namespace hula {

BandedMatrix::BandedMatrix(std::size_t n, std::size_t kl, std::size_t ku)
    : n_(n), kl_(kl), ku_(ku), width_(2 * kl + ku + 1), data_(n * (2 * kl + ku + 1), 0.0) {}

double& BandedMatrix::at(std::size_t i, std::size_t j) {
  HULA_ASSERT(j + kl_ >= i && j <= i + kl_ + ku_, "banded entry outside storage");
  return data_[i * width_ + (j + kl_ - i)];
}

double BandedMatrix::at(std::size_t i, std::size_t j) const {
  if (j + kl_ < i || j > i + kl_ + ku_) return 0.0;
  return data_[i * width_ + (j + kl_ - i)];
}

bool BandedMatrix::solve(std::span<double> rhs, std::size_t columns) {
  HULA_ASSERT(rhs.size() == n_ * columns, "banded rhs size mismatch");
  // Row scales for the relative singularity test.
  std::vector<double> scale(n_, 0.0);
  for (std::size_t i = 0; i < n_; ++i) {
    for (std::size_t k = 0; k < width_; ++k) scale[i] = std::max(scale[i], std::fabs(data_[i * width_ + k]));
    if (scale[i] == 0.0) return false;
  }
  constexpr double kSingular = 64 * std::numeric_limits<double>::epsilon();
  for (std::size_t k = 0; k < n_; ++k) {
    // Step 1: pivot = largest |a(i,k)| scaled by row, i in [k, k + kl].
    const std::size_t last = std::min(n_ - 1, k + kl_);
    std::size_t piv = k;
    double best = -1.0;
    for (std::size_t i = k; i <= last; ++i) {
      const double v = std::fabs(at(i, k)) / scale[i];
      if (v > best) best = v, piv = i;
    }
    if (!(best > kSingular)) return false;
    // Step 2: swap rows k and piv over columns k .. k + kl + ku (the band plus fill).
    const std::size_t jmax = std::min(n_ - 1, k + kl_ + ku_);
    if (piv != k) {
      for (std::size_t j = k; j <= jmax; ++j) std::swap(at(k, j), at(piv, j));
      for (std::size_t c = 0; c < columns; ++c) std::swap(rhs[k * columns + c], rhs[piv * columns + c]);
      std::swap(scale[k], scale[piv]);
    }
    // Step 3: eliminate below the pivot.
    const double pivot = at(k, k);
    for (std::size_t i = k + 1; i <= last; ++i) {
      const double f = at(i, k) / pivot;
      if (f == 0.0) continue;
      at(i, k) = 0.0;
      for (std::size_t j = k + 1; j <= jmax; ++j) at(i, j) -= f * at(k, j);
      for (std::size_t c = 0; c < columns; ++c) rhs[i * columns + c] -= f * rhs[k * columns + c];
    }
  }
  // Back substitution over the widened upper band.
  for (std::size_t kk = n_; kk-- > 0;) {
    const std::size_t jmax = std::min(n_ - 1, kk + kl_ + ku_);
    for (std::size_t c = 0; c < columns; ++c) {
      double s = rhs[kk * columns + c];
      for (std::size_t j = kk + 1; j <= jmax; ++j) s -= at(kk, j) * rhs[j * columns + c];
      rhs[kk * columns + c] = s / at(kk, kk);
    }
  }
  return true;
}

}  // namespace hula
