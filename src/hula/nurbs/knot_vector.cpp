// SPDX-License-Identifier: MIT
// Knot vector validation and span search (The NURBS Book A2.1). Span search
// uses exact comparisons: a parameter equal to a knot belongs to the span
// that starts there (Right) or ends there (Left); no epsilon is involved.
#include "hula/nurbs/knot_vector.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "hula/core/error.hpp"

namespace hula::nurbs {
namespace {

void validate(std::span<const double> U, int p, std::size_t index_offset, const char* field) {
  if (p < 1 || p > kMaxDegree)
    throw Error(Errc::InvalidDegree,
                "degree = " + std::to_string(p) + " must be in [1, " + std::to_string(kMaxDegree) + "]",
                {.field = "degree"});
  const auto pp = static_cast<std::size_t>(p);
  if (U.size() < 2 * (pp + 1))
    throw Error(Errc::InvalidKnots,
                std::string(field) + " has " + std::to_string(U.size() - 2 * index_offset) + " values; degree " +
                    std::to_string(p) + " needs at least " + std::to_string(2 * (pp + 1) - 2 * index_offset),
                {.field = field});
  for (std::size_t i = 0; i < U.size(); ++i) {
    if (!std::isfinite(U[i])) {
      const std::size_t idx = i >= index_offset ? i - index_offset : 0;
      throw Error(Errc::NonFiniteInput,
                  std::string(field) + "[" + std::to_string(idx) + "] = " + format_number(U[i]) + " is not finite",
                  {.field = field, .index = idx});
    }
  }
  for (std::size_t i = 1; i < U.size(); ++i) {
    if (U[i] < U[i - 1]) {
      const std::size_t idx = i - index_offset;
      throw Error(Errc::InvalidKnots,
                  std::string(field) + "[" + std::to_string(idx) + "] = " + format_number(U[i]) + " is less than " +
                      field + "[" + std::to_string(idx - 1) + "] = " + format_number(U[i - 1]) +
                      " (knot vector must be non-decreasing)",
                  {.field = field, .index = idx});
    }
  }
  const std::size_t m = U.size() - 1;
  const double a = U[pp], b = U[m - pp];
  if (!(a < b))
    throw Error(Errc::InvalidKnots,
                std::string(field) + " domain [" + format_number(a) + ", " + format_number(b) +
                    "] is empty (the knots at indices degree and m - degree must differ)",
                {.field = field, .index = pp - std::min(pp, index_offset)});
  for (std::size_t i = 0; i < U.size();) {
    std::size_t j = i;
    while (j + 1 < U.size() && U[j + 1] == U[i]) ++j;
    const std::size_t mult = j - i + 1;
    const bool interior = U[i] > a && U[i] < b;
    const std::size_t limit = interior ? pp : pp + 1;
    if (mult > limit) {
      const std::size_t idx = i >= index_offset ? i - index_offset : 0;
      throw Error(
          Errc::InvalidKnots,
          std::string(field) + "[" + std::to_string(idx) + "] = " + format_number(U[i]) + " has multiplicity " +
              std::to_string(mult) + " but at most " + std::to_string(limit) +
              (interior ? " is allowed inside the domain (degree, keeps the curve C0)" : " is allowed (degree + 1)"),
          {.field = field, .index = idx});
    }
    i = j + 1;
  }
}

}  // namespace

KnotVector::KnotVector(std::vector<double> knots, int degree) : knots_(std::move(knots)), degree_(degree) {
  validate(knots_, degree_, 0, "knots");
}

KnotVector KnotVector::from_acis(std::span<const double> knots, int degree) {
  if (knots.empty()) {
    validate(knots, degree, 0, "knots");  // reports the size problem
  }
  std::vector<double> full;
  full.reserve(knots.size() + 2);
  full.push_back(knots.front());
  full.insert(full.end(), knots.begin(), knots.end());
  full.push_back(knots.back());
  validate(full, degree, 1, "knots");
  return KnotVector(Unchecked{}, std::move(full), degree);
}

std::vector<double> KnotVector::to_acis() const { return {knots_.begin() + 1, knots_.end() - 1}; }

KnotVector KnotVector::uniform_clamped(std::size_t control_points, int degree, Interval domain) {
  if (degree < 1 || degree > kMaxDegree)
    throw Error(Errc::InvalidDegree,
                "degree = " + std::to_string(degree) + " must be in [1, " + std::to_string(kMaxDegree) + "]",
                {.field = "degree"});
  const auto p = static_cast<std::size_t>(degree);
  if (control_points < p + 1)
    throw Error(Errc::InvalidDegree,
                "degree = " + std::to_string(degree) + " needs at least " + std::to_string(p + 1) +
                    " control points, got " + std::to_string(control_points),
                {.field = "degree"});
  if (!(std::isfinite(domain.start) && std::isfinite(domain.end) && domain.start < domain.end))
    throw Error(Errc::InvalidArgument,
                "domain [" + format_number(domain.start) + ", " + format_number(domain.end) +
                    "] must be finite with start < end",
                {.field = "domain"});
  const std::size_t spans = control_points - p;
  std::vector<double> U;
  U.reserve(control_points + p + 1);
  for (std::size_t i = 0; i <= p; ++i) U.push_back(domain.start);
  for (std::size_t i = 1; i < spans; ++i)
    U.push_back(domain.start + domain.length() * static_cast<double>(i) / static_cast<double>(spans));
  for (std::size_t i = 0; i <= p; ++i) U.push_back(domain.end);
  return KnotVector(std::move(U), degree);
}

Interval KnotVector::domain() const noexcept {
  const auto p = static_cast<std::size_t>(degree_);
  return {knots_[p], knots_[knots_.size() - 1 - p]};
}

bool KnotVector::is_clamped() const noexcept {
  const auto p = static_cast<std::size_t>(degree_);
  const std::size_t m = knots_.size() - 1;
  for (std::size_t i = 0; i < p; ++i)
    if (knots_[i] != knots_[p] || knots_[m - i] != knots_[m - p]) return false;
  return true;
}

std::size_t KnotVector::find_span(double t, Side side) const noexcept {
  const auto p = static_cast<std::size_t>(degree_);
  const std::size_t n = control_point_count() - 1;
  const double* U = knots_.data();
  if (side == Side::Right) {
    // Largest i in [p, n] with U[i] <= t (spans starting at t belong to t).
    if (t >= U[n + 1]) {
      std::size_t i = n;
      while (i > p && U[i] == U[n + 1]) --i;  // last non-empty span
      return i;
    }
    if (t < U[p]) return p;
    const double* it = std::upper_bound(U + p, U + n + 1, t);
    return static_cast<std::size_t>(it - U) - 1;
  }
  // Left: smallest i in [p, n] with t <= U[i+1] and U[i] < U[i+1].
  if (t <= U[p]) {
    std::size_t i = p;
    while (i < n && U[i + 1] == U[p]) ++i;  // first non-empty span
    return i;
  }
  if (t > U[n + 1]) return n;
  const double* it = std::lower_bound(U + p + 1, U + n + 2, t);
  return static_cast<std::size_t>(it - U) - 1;
}

std::size_t KnotVector::find_span(double t, std::size_t hint, Side side) const noexcept {
  const auto p = static_cast<std::size_t>(degree_);
  const std::size_t n = control_point_count() - 1;
  const double* U = knots_.data();
  if (hint >= p && hint <= n && U[hint] < U[hint + 1]) {
    if (side == Side::Right) {
      if (U[hint] <= t && (t < U[hint + 1] || (hint == n && t <= U[n + 1]))) return hint;
    } else {
      if (U[hint] < t && t <= U[hint + 1]) return hint;
    }
  }
  return find_span(t, side);
}

int KnotVector::multiplicity(double u) const noexcept {
  const auto range = std::equal_range(knots_.begin(), knots_.end(), u);
  return static_cast<int>(range.second - range.first);
}

std::vector<double> KnotVector::breakpoints() const {
  const Interval d = domain();
  std::vector<double> out;
  for (double u : knots_)
    if (u >= d.start && u <= d.end && (out.empty() || out.back() != u)) out.push_back(u);
  return out;
}

KnotVector KnotVector::reparameterised(Interval target) const {
  if (!(std::isfinite(target.start) && std::isfinite(target.end) && target.start < target.end))
    throw Error(Errc::InvalidArgument,
                "target domain [" + format_number(target.start) + ", " + format_number(target.end) +
                    "] must be finite with start < end",
                {.field = "domain"});
  const Interval d = domain();
  const double scale = target.length() / d.length();
  std::vector<double> U(knots_.size());
  for (std::size_t i = 0; i < U.size(); ++i) U[i] = target.start + (knots_[i] - d.start) * scale;
  // Pin the domain ends exactly: rounding must not move them.
  for (std::size_t i = 0; i < U.size(); ++i) {
    if (knots_[i] == d.start) U[i] = target.start;
    if (knots_[i] == d.end) U[i] = target.end;
  }
  return KnotVector(std::move(U), degree_);
}

}  // namespace hula::nurbs
