// SPDX-License-Identifier: MIT
#include "hula/optim/pareto.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "hula/core/error.hpp"

namespace hula::optim {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

bool pareto_dominates(const double* a, const double* b, std::size_t m) noexcept {
  bool strictly = false;
  for (std::size_t j = 0; j < m; ++j) {
    if (a[j] > b[j]) return false;
    if (a[j] < b[j]) strictly = true;
  }
  return strictly;
}

// True when the k points at idx, sorted by f0 (ties by index), are mutually non-dominated in two
// objectives: f1 strictly decreases from one point to the next unless the two are equal in both (then
// nothing dominates either). NaN anywhere fails the test.
bool mutually_non_dominated_2d(const double* f, const std::size_t* idx, std::size_t k) noexcept {
  for (std::size_t q = 1; q < k; ++q) {
    const double* a = f + idx[q - 1] * 2;
    const double* b = f + idx[q] * 2;
    const bool equal = b[0] == a[0] && b[1] == a[1];
    if (!(equal || (b[0] > a[0] && b[1] < a[1]))) return false;
  }
  return true;
}

// Exact 2-D hypervolume of points already filtered to dominate the reference.
double hv2d(std::vector<double>& pts, std::size_t n, std::size_t stride, const double* ref) {
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    const double* pa = &pts[a * stride];
    const double* pb = &pts[b * stride];
    return pa[0] < pb[0] || (pa[0] == pb[0] && pa[1] < pb[1]);
  });
  double area = 0.0;
  double prev = ref[1];
  for (const std::size_t i : idx) {
    const double* p = &pts[i * stride];
    if (p[1] < prev) {
      area += (ref[0] - p[0]) * (prev - p[1]);
      prev = p[1];
    }
  }
  return area;
}

// HSO: slice along the last objective; each slab's cross-section is the
// (m-1)-dimensional hypervolume of the points below it.
double hv_rec(std::vector<double>& pts, std::size_t n, std::size_t m, const double* ref) {
  if (n == 0) return 0.0;
  if (m == 1) {
    double lo = ref[0];
    for (std::size_t i = 0; i < n; ++i) lo = std::min(lo, pts[i * m]);
    return ref[0] - lo;
  }
  if (m == 2) return hv2d(pts, n, 2, ref);
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  std::sort(idx.begin(), idx.end(),
            [&](std::size_t a, std::size_t b) { return pts[a * m + m - 1] < pts[b * m + m - 1]; });
  double volume = 0.0;
  std::vector<double> slab;
  slab.reserve(n * (m - 1));
  for (std::size_t i = 0; i < n; ++i) {
    const double z = pts[idx[i] * m + m - 1];
    const double z_next = i + 1 < n ? pts[idx[i + 1] * m + m - 1] : ref[m - 1];
    const double* p = &pts[idx[i] * m];
    slab.insert(slab.end(), p, p + (m - 1));
    if (z_next > z) {
      std::vector<double> copy = slab;
      volume += hv_rec(copy, i + 1, m - 1, ref) * (z_next - z);
    }
  }
  return volume;
}
}  // namespace

bool constrained_dominates(std::span<const double> a, double violation_a, std::span<const double> b,
                           double violation_b) noexcept {
  const bool fa = violation_a == 0.0;
  const bool fb = violation_b == 0.0;
  if (fa && !fb) return true;
  if (!fa && fb) return false;
  if (!fa) return violation_a < violation_b;
  return pareto_dominates(a.data(), b.data(), a.size());
}

std::span<const std::size_t> NonDominatedSorter::sort(std::span<const double> objectives, std::size_t m,
                                                      std::span<const double> violation) {
  const std::size_t n = m ? objectives.size() / m : 0;
  // Reserve every buffer for n points so that later calls of the same size
  // never allocate (NSGA-II sorts 2N points every generation).
  for (auto* buffer : {&order_, &next_, &current_, &last_, &start_, &next_front_, &count_}) buffer->reserve(n + 1);
  keys_.reserve(n);
  rank_.assign(n, 0);
  order_.clear();    // feasible
  next_.clear();     // infeasible
  current_.clear();  // failed
  for (std::size_t i = 0; i < n; ++i) {
    const double v = violation.empty() ? 0.0 : violation[i];
    bool failed = !std::isfinite(v);
    for (std::size_t j = 0; j < m && !failed; ++j) failed = std::isnan(objectives[i * m + j]);
    if (failed) {
      current_.push_back(i);
    } else if (v > 0.0) {
      next_.push_back(i);
    } else {
      order_.push_back(i);
    }
  }
  const double* f = objectives.data();
  std::size_t fronts = 0;
  if (!order_.empty()) {
    if (m == 2) {
      // Lexicographic order: every dominator of a point precedes it. Sorting the keys themselves rather
      // than indices into `objectives` keeps the comparisons in cache.
      keys_.resize(order_.size());
      for (std::size_t k = 0; k < order_.size(); ++k) keys_[k] = {f[order_[k] * 2], f[order_[k] * 2 + 1], order_[k]};
      std::sort(keys_.begin(), keys_.end(), [](const Key2& a, const Key2& b) {
        if (a.f0 != b.f0) return a.f0 < b.f0;
        if (a.f1 != b.f1) return a.f1 < b.f1;
        return a.index < b.index;
      });
      for (std::size_t k = 0; k < order_.size(); ++k) order_[k] = keys_[k].index;
    } else if (m == 1) {
      std::sort(order_.begin(), order_.end(),
                [&](std::size_t a, std::size_t b) { return f[a] < f[b] || (f[a] == f[b] && a < b); });
    }
    if (m <= 2) {
      if (m == 1) {
        for (std::size_t k = 0; k < order_.size(); ++k) {
          if (k > 0 && f[order_[k]] > f[order_[k - 1]]) ++fronts;
          rank_[order_[k]] = fronts;
        }
        ++fronts;
      } else {
        // last_[k] = member of front k with the smallest f1 so far (as a position in keys_, whose
        // objectives sit beside it); front k dominates p iff last_[k] does, and that holds for a
        // prefix of k. The domination test is pareto_dominates' on the keys' own copies, evaluated
        // without branches (the search's direction is data).
        last_.clear();
        for (std::size_t k = 0; k < keys_.size(); ++k) {
          const Key2& p = keys_[k];
          std::size_t lo = 0;
          std::size_t hi = last_.size();
          while (lo < hi) {
            const std::size_t mid = (lo + hi) / 2;
            const Key2& t = keys_[last_[mid]];
            const bool dominated = (t.f0 <= p.f0) & (t.f1 <= p.f1) & ((t.f0 < p.f0) | (t.f1 < p.f1));
            lo = dominated ? mid + 1 : lo;
            hi = dominated ? hi : mid;
          }
          if (lo == last_.size()) {
            last_.push_back(k);
          } else {
            last_[lo] = k;
          }
          rank_[p.index] = lo;
        }
        fronts = last_.size();
      }
    } else {
      // Deb's fast non-dominated sort with flat domination lists.
      const std::size_t nf = order_.size();
      count_.assign(nf, 0);
      start_.assign(nf + 1, 0);
      dominated_.resize(nf * nf);
      std::vector<std::size_t>& fill = last_;
      fill.assign(nf, 0);
      for (std::size_t a = 0; a < nf; ++a) {
        for (std::size_t b = a + 1; b < nf; ++b) {
          const double* pa = f + order_[a] * m;
          const double* pb = f + order_[b] * m;
          if (pareto_dominates(pa, pb, m)) {
            dominated_[a * nf + fill[a]++] = b;
            ++count_[b];
          } else if (pareto_dominates(pb, pa, m)) {
            dominated_[b * nf + fill[b]++] = a;
            ++count_[a];
          }
        }
      }
      std::vector<std::size_t>& cur = start_;
      cur.clear();
      for (std::size_t a = 0; a < nf; ++a) {
        if (count_[a] == 0) cur.push_back(a);
      }
      std::vector<std::size_t>& nxt = next_front_;
      while (!cur.empty()) {
        nxt.clear();
        for (const std::size_t a : cur) {
          rank_[order_[a]] = fronts;
          for (std::size_t k = 0; k < fill[a]; ++k) {
            const std::size_t b = dominated_[a * nf + k];
            if (--count_[b] == 0) nxt.push_back(b);
          }
        }
        cur.swap(nxt);
        ++fronts;
      }
    }
  }
  if (!next_.empty()) {
    std::sort(next_.begin(), next_.end(), [&](std::size_t a, std::size_t b) {
      return violation[a] < violation[b] || (violation[a] == violation[b] && a < b);
    });
    for (std::size_t k = 0; k < next_.size(); ++k) {
      if (k > 0 && violation[next_[k]] > violation[next_[k - 1]]) ++fronts;
      rank_[next_[k]] = fronts;
    }
    ++fronts;
  }
  if (!current_.empty()) {
    for (const std::size_t i : current_) rank_[i] = fronts;
    ++fronts;
  }
  fronts_ = fronts;
  return rank_;
}

ParetoRanking non_dominated_sort(std::span<const double> objectives, std::size_t m, std::span<const double> violation) {
  NonDominatedSorter sorter;
  const auto r = sorter.sort(objectives, m, violation);
  return {std::vector<std::size_t>(r.begin(), r.end()), sorter.fronts()};
}

void crowding_distance(std::span<const double> objectives, std::size_t m, std::span<const std::size_t> front,
                       std::span<double> distance, std::span<std::size_t> scratch) noexcept {
  const std::size_t k = front.size();
  for (const std::size_t i : front) distance[i] = 0.0;
  if (k <= 2) {
    for (const std::size_t i : front) distance[i] = kInf;
    return;
  }
  std::copy(front.begin(), front.end(), scratch.begin());
  const double* f = objectives.data();
  const auto first = scratch.begin();
  const auto last = scratch.begin() + static_cast<std::ptrdiff_t>(k);
  for (std::size_t j = 0; j < m; ++j) {
    const auto by_objective = [&](std::size_t a, std::size_t b) {
      return f[a * m + j] < f[b * m + j] || (f[a * m + j] == f[b * m + j] && a < b);
    };
    if (m == 2 && j == 1 && mutually_non_dominated_2d(f, scratch.data(), k)) {
      // Sorted by f1 (ties by index), a 2-D non-dominated set is its f0 order reversed, except that runs
      // of equal points (equal in both objectives) keep their index order: the same permutation the sort
      // below gives, without sorting (NSGA-II's own cost per generation).
      std::reverse(first, last);
      for (auto run = first; run != last;) {
        auto end = run + 1;
        while (end != last && f[*end * 2] == f[*run * 2] && f[*end * 2 + 1] == f[*run * 2 + 1]) ++end;
        std::reverse(run, end);
        run = end;
      }
    } else if (!std::is_sorted(first, last, by_objective)) {
      // NSGA-II hands 2-D fronts over already in f0 order.
      std::sort(first, last, by_objective);
    }
    distance[scratch[0]] = kInf;
    distance[scratch[k - 1]] = kInf;
    const double range = f[scratch[k - 1] * m + j] - f[scratch[0] * m + j];
    if (!(range > 0.0)) continue;
    for (std::size_t q = 1; q + 1 < k; ++q) {
      distance[scratch[q]] += (f[scratch[q + 1] * m + j] - f[scratch[q - 1] * m + j]) / range;
    }
  }
}

std::vector<std::size_t> thin_by_crowding(std::span<const double> objectives, std::size_t m, std::size_t keep) {
  const std::size_t n = m == 0 ? 0 : objectives.size() / m;
  std::vector<std::size_t> members(n);
  std::iota(members.begin(), members.end(), std::size_t{0});
  std::vector<double> distance(n);
  std::vector<std::size_t> scratch(n);
  while (members.size() > keep) {
    crowding_distance(objectives, m, members, distance, scratch);
    const auto worst = std::min_element(members.begin(), members.end(), [&](std::size_t a, std::size_t b) {
      return distance[a] < distance[b] || (distance[a] == distance[b] && a < b);
    });
    members.erase(worst);
  }
  return members;
}

double hypervolume(std::span<const double> points, std::size_t m, std::span<const double> reference) {
  if (m == 0) throw Error(Errc::InvalidArgument, "objectives m = 0 must be >= 1", {.field = "m"});
  if (reference.size() != m) {
    throw Error(Errc::InvalidArgument,
                "reference has " + std::to_string(reference.size()) + " values, expected m = " + std::to_string(m),
                {.field = "reference"});
  }
  if (points.size() % m != 0) {
    throw Error(Errc::InvalidArgument,
                "points has " + std::to_string(points.size()) + " values, not a multiple of m = " + std::to_string(m),
                {.field = "points"});
  }
  for (std::size_t j = 0; j < m; ++j) {
    if (!std::isfinite(reference[j])) {
      throw Error(Errc::NonFiniteInput, "reference[" + std::to_string(j) + "] = " + format_number(reference[j]),
                  {.field = "reference", .index = j});
    }
  }
  const std::size_t n = points.size() / m;
  std::vector<double> kept;
  kept.reserve(points.size());
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    bool inside = true;
    for (std::size_t j = 0; j < m; ++j) {
      const double v = points[i * m + j];
      if (!std::isfinite(v)) {
        throw Error(Errc::NonFiniteInput,
                    "points[" + std::to_string(i) + "][" + std::to_string(j) + "] = " + format_number(v),
                    {.field = "points", .index = i, .component = j});
      }
      inside = inside && v < reference[j];
    }
    if (!inside) continue;
    kept.insert(kept.end(), points.begin() + static_cast<std::ptrdiff_t>(i * m),
                points.begin() + static_cast<std::ptrdiff_t>((i + 1) * m));
    ++count;
  }
  return hv_rec(kept, count, m, reference.data());
}

}  // namespace hula::optim
