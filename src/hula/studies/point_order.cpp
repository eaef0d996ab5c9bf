// SPDX-License-Identifier: MIT
// order_along_curve: kd-tree k-nearest neighbours, Kruskal's minimum spanning
// tree on the k-NN graph, the tree's diameter by two traversals, and keys by a
// multi-source traversal from the diameter path (see point_order.hpp).
#include "hula/studies/point_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

#include "hula/core/error.hpp"

namespace hula::studies {

void PointOrderOptions::validate() const {
  if (neighbours < 2 || neighbours > 64)
    throw Error(Errc::InvalidOption, "neighbours must be in [2, 64], got " + std::to_string(neighbours),
                ErrorWhere{.field = "neighbours"});
  if (!(isolation_factor > 1.0) || !std::isfinite(isolation_factor))
    throw Error(Errc::InvalidOption, "isolation_factor must be > 1 and finite, got " + std::to_string(isolation_factor),
                ErrorWhere{.field = "isolation_factor"});
}

namespace {

double coord(const Vec3& v, int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }

// A balanced kd-tree over an index permutation: node [lo, hi) splits at mid on `axis`.
class KdTree {
 public:
  explicit KdTree(std::span<const Vec3> pts) : pts_(pts), idx_(pts.size()), axis_(pts.size(), 0) {
    std::iota(idx_.begin(), idx_.end(), std::size_t{0});
    build(0, idx_.size());
  }

  // The k nearest points to point q (q itself excluded), as (squared distance, index), nearest first.
  void knn(std::size_t q, std::size_t k, std::vector<std::pair<double, std::size_t>>& heap) const {
    heap.clear();
    search(0, idx_.size(), q, k, heap);
    std::sort_heap(heap.begin(), heap.end());
  }

 private:
  void build(std::size_t lo, std::size_t hi) {
    if (hi - lo <= 1) return;
    Vec3 mn = pts_[idx_[lo]], mx = mn;
    for (std::size_t i = lo; i < hi; ++i) {
      const Vec3& p = pts_[idx_[i]];
      mn = {std::min(mn.x, p.x), std::min(mn.y, p.y), std::min(mn.z, p.z)};
      mx = {std::max(mx.x, p.x), std::max(mx.y, p.y), std::max(mx.z, p.z)};
    }
    const Vec3 ext = mx - mn;
    const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
    const std::size_t mid = lo + (hi - lo) / 2;
    std::nth_element(idx_.begin() + static_cast<std::ptrdiff_t>(lo), idx_.begin() + static_cast<std::ptrdiff_t>(mid),
                     idx_.begin() + static_cast<std::ptrdiff_t>(hi),
                     [&](std::size_t a, std::size_t b) { return coord(pts_[a], axis) < coord(pts_[b], axis); });
    axis_[mid] = axis;
    build(lo, mid);
    build(mid + 1, hi);
  }

  void search(std::size_t lo, std::size_t hi, std::size_t q, std::size_t k,
              std::vector<std::pair<double, std::size_t>>& heap) const {
    if (lo >= hi) return;
    const std::size_t mid = lo + (hi - lo) / 2;
    const std::size_t i = idx_[mid];
    if (i != q) {
      const double d = norm_squared(pts_[i] - pts_[q]);
      if (heap.size() < k) {
        heap.emplace_back(d, i);
        std::push_heap(heap.begin(), heap.end());
      } else if (d < heap.front().first) {
        std::pop_heap(heap.begin(), heap.end());
        heap.back() = {d, i};
        std::push_heap(heap.begin(), heap.end());
      }
    }
    if (hi - lo == 1) return;
    const int axis = axis_[mid];
    const double delta = coord(pts_[q], axis) - coord(pts_[i], axis);
    const bool left_first = delta < 0.0;
    if (left_first)
      search(lo, mid, q, k, heap);
    else
      search(mid + 1, hi, q, k, heap);
    if (heap.size() < k || delta * delta < heap.front().first) {
      if (left_first)
        search(mid + 1, hi, q, k, heap);
      else
        search(lo, mid, q, k, heap);
    }
  }

  std::span<const Vec3> pts_;
  std::vector<std::size_t> idx_;
  std::vector<int> axis_;
};

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

struct Edge {
  double length;
  std::size_t a, b;
};

// Farthest node from `start` in the forest component of `start` (tree distances), with parents.
std::size_t farthest(const std::vector<std::vector<std::pair<std::size_t, double>>>& adj, std::size_t start,
                     std::vector<double>& dist, std::vector<std::size_t>& parent) {
  constexpr double kUnvisited = -1.0;
  std::fill(dist.begin(), dist.end(), kUnvisited);
  std::vector<std::size_t> stack{start};
  dist[start] = 0.0;
  parent[start] = start;
  std::size_t best = start;
  while (!stack.empty()) {
    const std::size_t u = stack.back();
    stack.pop_back();
    if (dist[u] > dist[best]) best = u;
    for (const auto& [v, w] : adj[u])
      if (dist[v] == kUnvisited) {
        dist[v] = dist[u] + w;
        parent[v] = u;
        stack.push_back(v);
      }
  }
  return best;
}

}  // namespace

PointOrder order_along_curve(std::span<const Vec3> points, const PointOrderOptions& options) {
  options.validate();
  const std::size_t n = points.size();
  if (n < 3)
    throw Error(Errc::TooFewPoints, "ordering needs at least 3 points, got " + std::to_string(n),
                ErrorWhere{.field = "points"});
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) || !std::isfinite(points[i].z))
      throw Error(Errc::NonFiniteInput, "point " + std::to_string(i) + " is not finite",
                  ErrorWhere{.field = "points", .index = i});
  const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(options.neighbours), n - 1);

  // 1. k nearest neighbours and each point's mean neighbour distance (the isolation test).
  const KdTree tree(points);
  std::vector<Edge> edges;
  edges.reserve(n * k);
  std::vector<double> spread(n);
  std::vector<std::pair<double, std::size_t>> heap;
  for (std::size_t i = 0; i < n; ++i) {
    tree.knn(i, k, heap);
    double sum = 0.0;
    for (const auto& [d2, j] : heap) {
      const double d = std::sqrt(d2);
      sum += d;
      edges.push_back({d, std::min(i, j), std::max(i, j)});
    }
    spread[i] = sum / static_cast<double>(k);
  }
  std::vector<double> sorted_spread = spread;
  std::nth_element(sorted_spread.begin(), sorted_spread.begin() + static_cast<std::ptrdiff_t>(n / 2),
                   sorted_spread.end());
  const double median_spread = sorted_spread[n / 2];
  if (!(median_spread > 0.0) && *std::max_element(spread.begin(), spread.end()) == 0.0)
    throw Error(Errc::CoincidentPoints, "all points coincide", ErrorWhere{.field = "points"});
  std::vector<char> isolated(n, 0);
  PointOrder out;
  for (std::size_t i = 0; i < n; ++i)
    if (spread[i] > options.isolation_factor * median_spread) {
      isolated[i] = 1;
      out.isolated.push_back(i);
    }

  // 2. Kruskal's minimum spanning forest over the edges between non-isolated points.
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
    return a.length < b.length || (a.length == b.length && (a.a < b.a || (a.a == b.a && a.b < b.b)));
  });
  std::vector<std::size_t> root(n);
  std::iota(root.begin(), root.end(), std::size_t{0});
  std::vector<std::vector<std::pair<std::size_t, double>>> adj(n);
  for (const Edge& e : edges) {
    if (isolated[e.a] || isolated[e.b]) continue;
    const std::size_t ra = find_root(root, e.a), rb = find_root(root, e.b);
    if (ra == rb) continue;
    root[ra] = rb;
    adj[e.a].emplace_back(e.b, e.length);
    adj[e.b].emplace_back(e.a, e.length);
  }

  // 3. The largest component's diameter: farthest node a from any node, then farthest b from a.
  std::vector<std::size_t> size(n, 0);
  std::size_t first = n;
  for (std::size_t i = 0; i < n; ++i)
    if (!isolated[i]) {
      const std::size_t r = find_root(root, i);
      if (++size[r] > (first == n ? 0 : size[find_root(root, first)])) first = i;
    }
  if (first == n) first = 0;  // every point isolated cannot happen (the median is not isolated)
  std::vector<double> dist(n);
  std::vector<std::size_t> parent(n);
  const std::size_t a = farthest(adj, first, dist, parent);
  const std::size_t b = farthest(adj, a, dist, parent);
  out.path_length = dist[b];

  // 4. Keys: the path nodes carry their arc length from a; every other node of the component
  //    inherits the key of the path node its branch hangs from (multi-source traversal).
  constexpr double kNoKey = -1.0;
  std::vector<double> key(n, kNoKey);
  std::vector<std::size_t> stack;
  for (std::size_t v = b;; v = parent[v]) {
    key[v] = out.path_length > 0.0 ? dist[v] / out.path_length : 0.0;
    stack.push_back(v);
    if (v == a) break;
  }
  while (!stack.empty()) {
    const std::size_t u = stack.back();
    stack.pop_back();
    for (const auto& [v, w] : adj[u])
      if (key[v] == kNoKey) {
        key[v] = key[u];
        stack.push_back(v);
      }
  }
  // 5. Points outside the component (isolated ones, other clusters) take their nearest keyed point's key.
  std::vector<std::size_t> keyed;
  for (std::size_t i = 0; i < n; ++i)
    if (key[i] != kNoKey) keyed.push_back(i);
  for (std::size_t i = 0; i < n; ++i) {
    if (key[i] != kNoKey) continue;
    double best = std::numeric_limits<double>::infinity();
    double best_key = 0.0;
    for (std::size_t j : keyed) {
      const double d = norm_squared(points[j] - points[i]);
      if (d < best) {
        best = d;
        best_key = key[j];
      }
    }
    key[i] = best_key;
  }
  out.key = std::move(key);
  out.order.resize(n);
  std::iota(out.order.begin(), out.order.end(), std::size_t{0});
  std::stable_sort(out.order.begin(), out.order.end(),
                   [&](std::size_t x, std::size_t y) { return out.key[x] < out.key[y]; });
  return out;
}

}  // namespace hula::studies
