// SPDX-License-Identifier: MIT
// Shared by integrate.cpp and antiderivative.cpp: which singularities make an
// end improper, and a law re-expanded about a point so that the distance to it
// is exact.
#pragma once

#include <string_view>

#include "hula/law/expr.hpp"
#include "hula/law/singularities.hpp"

namespace hula::law::detail {

/// True for the kinds where a law is unbounded, undefined or infinitely steep (poles, boundaries of
/// sqrt, log, powers, asin/acos, tan poles, atan2 and normalize at the origin), as opposed to kinks and
/// jumps.
[[nodiscard]] bool is_improper_kind(SingularityKind kind) noexcept;

/// f(t0 + dir·u) as a law of the same parameter (read as u ≥ 0), dir = ±1, simplified (law::simplify)
/// so that t − t0 becomes u exactly; f itself when t0 = 0 and dir = +1.
[[nodiscard]] Law shifted_law(const Law& f, std::string_view parameter, double t0, double dir);

/// Exponents of the growth |f| ≈ C |t − t0|^p within this of −1 count as −1 (not integrable).
inline constexpr double kGrowthSlack = 1e-3;

/// p of |g(u)| ≈ C u^p as u → 0+, from u = w·1e-8 and w·1e-12, for g a law re-expanded about a point
/// (shifted_law); +infinity where g vanishes faster than any power, −infinity where it overflows, NaN
/// where it is undefined there.
[[nodiscard]] double growth_exponent(const Law& g, std::string_view parameter, double w);

/// True when a growth exponent near a finite point is integrable: p > −1 + kGrowthSlack.
[[nodiscard]] inline bool integrable_growth(double p) noexcept { return p > -1.0 + kGrowthSlack; }

}  // namespace hula::law::detail
