// SPDX-License-Identifier: MIT
// order_along_curve: kd-tree k-nearest neighbours, Kruskal's minimum spanning
// tree on the k-NN graph, the tree's diameter by two traversals, and keys by a
// multi-source traversal from the diameter path (see point_order.hpp).
#include "hula/studies/point_order.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
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

  // The nearest point to point q for which `accept` holds, if nearer than √best_d2: updates best_d2 and
  // best and returns whether it found one. Nodes farther than the bound are pruned, so a good starting
  // bound keeps the search local.
  template <class Accept>
  bool nearest_accepted(std::size_t q, const Accept& accept, double& best_d2, std::size_t& best) const {
    bool found = false;
    nearest_accepted(0, idx_.size(), q, accept, best_d2, best, found);
    return found;
  }

 private:
  template <class Accept>
  void nearest_accepted(std::size_t lo, std::size_t hi, std::size_t q, const Accept& accept, double& best_d2,
                        std::size_t& best, bool& found) const {
    if (lo >= hi) return;
    const std::size_t mid = lo + (hi - lo) / 2;
    const std::size_t i = idx_[mid];
    if (i != q && accept(i)) {
      const double d = norm_squared(pts_[i] - pts_[q]);
      if (d < best_d2) {
        best_d2 = d;
        best = i;
        found = true;
      }
    }
    if (hi - lo == 1) return;
    const int axis = axis_[mid];
    const double delta = coord(pts_[q], axis) - coord(pts_[i], axis);
    const bool left_first = delta < 0.0;
    if (left_first)
      nearest_accepted(lo, mid, q, accept, best_d2, best, found);
    else
      nearest_accepted(mid + 1, hi, q, accept, best_d2, best, found);
    if (delta * delta < best_d2) {
      if (left_first)
        nearest_accepted(mid + 1, hi, q, accept, best_d2, best, found);
      else
        nearest_accepted(lo, mid, q, accept, best_d2, best, found);
    }
  }

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

// The minimum spanning forest of the k-NN graph of the non-isolated points, its largest
// component's longest path, and where every point hangs from that path.
struct Tree {
  std::vector<std::size_t> path;    // path nodes from one end (a) to the other (b)
  std::vector<double> path_s;       // arc length along the path at each node
  std::vector<std::size_t> attach;  // per point: index into path of the node its branch hangs from (npos: none)
  std::vector<std::size_t> isolated;
  std::vector<double> radius;  // per point: distance to its k-th nearest neighbour
};

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

void check_points(std::span<const Vec3> points) {
  const std::size_t n = points.size();
  if (n < 3)
    throw Error(Errc::TooFewPoints, "ordering needs at least 3 points, got " + std::to_string(n),
                ErrorWhere{.field = "points"});
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) || !std::isfinite(points[i].z))
      throw Error(Errc::NonFiniteInput, "point " + std::to_string(i) + " is not finite",
                  ErrorWhere{.field = "points", .index = i});
}

// Pieces of the forest smaller than this stay unjoined (at most a detour of three points, see order_points).
constexpr std::size_t kMinPiece = 4;

// Joins the forest's pieces of at least kMinPiece non-isolated points into one tree: in rounds, every piece
// but the largest adds its shortest edge to a point outside it (a Borůvka step; each round at least halves
// the pieces), until one remains.
void connect_pieces(const KdTree& kd, std::span<const Vec3> points, const std::vector<char>& isolated,
                    std::vector<std::size_t>& root, std::vector<std::vector<std::pair<std::size_t, double>>>& adj) {
  const std::size_t n = points.size();
  for (;;) {
    std::vector<std::size_t> size(n, 0);
    for (std::size_t i = 0; i < n; ++i)
      if (!isolated[i]) ++size[find_root(root, i)];
    std::size_t largest = n, pieces = 0;
    for (std::size_t r = 0; r < n; ++r)
      if (size[r] >= kMinPiece) {
        ++pieces;
        if (largest == n || size[r] > size[largest]) largest = r;
      }
    if (pieces < 2) return;
    // Per piece (its root): the shortest edge out of it found so far.
    std::vector<double> best_d2(n, std::numeric_limits<double>::infinity());
    std::vector<std::pair<std::size_t, std::size_t>> best_edge(n, {n, n});
    for (std::size_t i = 0; i < n; ++i) {
      if (isolated[i]) continue;
      const std::size_t r = find_root(root, i);
      if (r == largest || size[r] < kMinPiece) continue;
      std::size_t j = n;
      if (kd.nearest_accepted(
              i,
              [&](std::size_t c) {
                if (isolated[c]) return false;
                const std::size_t rc = find_root(root, c);
                return rc != r && size[rc] >= kMinPiece;
              },
              best_d2[r], j))
        best_edge[r] = {i, j};
    }
    for (std::size_t r = 0; r < n; ++r) {
      const auto [i, j] = best_edge[r];
      if (i == n) continue;
      const std::size_t ri = find_root(root, i), rj = find_root(root, j);
      if (ri == rj) continue;
      root[ri] = rj;
      const double d = std::sqrt(best_d2[r]);
      adj[i].emplace_back(j, d);
      adj[j].emplace_back(i, d);
    }
  }
}

Tree build_tree(std::span<const Vec3> points, const PointOrderOptions& options) {
  const std::size_t n = points.size();
  const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(options.neighbours), n - 1);

  // 1. k nearest neighbours, each point's mean neighbour distance (the isolation test) and radius.
  const KdTree kd(points);
  std::vector<Edge> edges;
  edges.reserve(n * k);
  std::vector<double> spread(n);
  Tree tree;
  tree.radius.resize(n);
  std::vector<std::pair<double, std::size_t>> heap;
  for (std::size_t i = 0; i < n; ++i) {
    kd.knn(i, k, heap);
    double sum = 0.0;
    for (const auto& [d2, j] : heap) {
      const double d = std::sqrt(d2);
      sum += d;
      edges.push_back({d, std::min(i, j), std::max(i, j)});
    }
    spread[i] = sum / static_cast<double>(k);
    tree.radius[i] = heap.empty() ? 0.0 : std::sqrt(heap.back().first);
  }
  std::vector<double> sorted_spread = spread;
  std::nth_element(sorted_spread.begin(), sorted_spread.begin() + static_cast<std::ptrdiff_t>(n / 2),
                   sorted_spread.end());
  const double median_spread = sorted_spread[n / 2];
  if (!(median_spread > 0.0) && *std::max_element(spread.begin(), spread.end()) == 0.0)
    throw Error(Errc::CoincidentPoints, "all points coincide", ErrorWhere{.field = "points"});
  std::vector<char> isolated(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (spread[i] > options.isolation_factor * median_spread) {
      isolated[i] = 1;
      tree.isolated.push_back(i);
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

  // 3. The k-NN graph falls apart where the sampling leaves a gap wider than k spacings: its pieces of at
  // least kMinPiece points are joined, Borůvka-fashion, by their shortest edges to the rest (the
  // Euclidean MST does the same), so the path runs across the gaps instead of ending at the first.
  // Smaller pieces (a stray pair, a detour) stay out and hang from their nearest tree point.
  connect_pieces(kd, points, isolated, root, adj);

  // 4. The largest component's diameter: farthest node a from any node, then farthest b from a.
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
  for (std::size_t v = b;; v = parent[v]) {
    tree.path.push_back(v);
    if (v == a) break;
  }
  std::reverse(tree.path.begin(), tree.path.end());  // from a to b
  for (const std::size_t v : tree.path) tree.path_s.push_back(dist[v]);

  // 5. Every other node of the component inherits the path node its branch hangs from.
  tree.attach.assign(n, kNone);
  std::vector<std::size_t> stack;
  for (std::size_t j = 0; j < tree.path.size(); ++j) {
    tree.attach[tree.path[j]] = j;
    stack.push_back(tree.path[j]);
  }
  while (!stack.empty()) {
    const std::size_t u = stack.back();
    stack.pop_back();
    for (const auto& [v, w] : adj[u])
      if (tree.attach[v] == kNone) {
        tree.attach[v] = tree.attach[u];
        stack.push_back(v);
      }
  }
  return tree;
}

// Index of the attached point nearest to point i (for points outside the tree's component).
std::size_t nearest_attached(std::span<const Vec3> points, const Tree& tree, std::size_t i) {
  double best = std::numeric_limits<double>::infinity();
  std::size_t arg = tree.path.front();
  for (std::size_t j = 0; j < points.size(); ++j) {
    if (tree.attach[j] == kNone) continue;
    const double d = norm_squared(points[j] - points[i]);
    if (d < best) {
      best = d;
      arg = j;
    }
  }
  return arg;
}

double angle_cosine(const Vec3& a, const Vec3& b) {
  const double na = norm(a), nb = norm(b);
  return na > 0.0 && nb > 0.0 ? dot(a, b) / (na * nb) : -1.0;
}

// Two directions differ by less than 60°.
constexpr double kSmoothJoinCosine = 0.5;

// Two directions differ by less than 45°: a gap in the sampling must continue the curve's direction on
// both sides (the tangent turns by less than 90° across it).
constexpr double kGapCosine = 0.7071067811865476;
// Points on each side of a gap whose run gives the direction there (two halves' centroids).
constexpr std::size_t kGapRun = 8;
// Points skipped by a detour, at most.
constexpr std::size_t kMaxDetour = 3;

// The coordinate-wise median of the points `which` (the mean of the middle two for an even count).
Vec3 median_point(std::span<const Vec3> points, std::span<const std::size_t> which) {
  std::array<std::vector<double>, 3> c;
  for (const std::size_t i : which) {
    c[0].push_back(points[i].x);
    c[1].push_back(points[i].y);
    c[2].push_back(points[i].z);
  }
  std::array<double, 3> m{};
  for (std::size_t a = 0; a < 3; ++a) {
    std::sort(c[a].begin(), c[a].end());
    const std::size_t h = c[a].size() / 2;
    m[a] = c[a].size() % 2 == 1 ? c[a][h] : 0.5 * (c[a][h - 1] + c[a][h]);
  }
  return {m[0], m[1], m[2]};
}

// Whether the points `suspect` leaves out follow one another in the file (see order_points). A step is
// local when it is no longer than twice the larger k-th neighbour distance of its two points (the
// density's own scale: where the sampling is three times sparser, so are the radii). A step that is not
// local is taken
//  - as a detour when one to three points are skipped and the step after them is local (strays in the
//    file, at either end too: an end's first or last one to three points);
//  - as a gap in the sampling when the step continues the directions of the points before it and after it
//    (each within 45°; up to eight points a side, directions from medians) and no more than three points of the cloud
//    lie within the neighbour radius of the step's segment away from its ends (a gap is empty: a jump back over the
//    curve, to a later stretch or across a loop, passes over points or turns);
// anything else breaks the order. Detours may skip at most a tenth of the points and the gaps number at
// most 1 + n / 100, so a shuffled file (almost no local step) or one with a stretch out of place (a
// step that turns back) is refused. Marks the skipped points in `suspect`.
bool file_order_is_consistent(std::span<const Vec3> points, const Tree& tree, std::vector<char>& suspect) {
  const std::size_t n = points.size();
  std::vector<std::size_t> seq;
  for (std::size_t i = 0; i < n; ++i)
    if (!suspect[i]) seq.push_back(i);
  const std::size_t m = seq.size();
  if (m < 3) return false;
  const auto local = [&](std::size_t a, std::size_t b) {
    return distance(points[a], points[b]) <= 2.0 * std::max(tree.radius[a], tree.radius[b]);
  };
  std::vector<std::size_t> kept;  // the points taken in order so far
  std::size_t detours = 0, gaps = 0;
  // A gap from kept.back() to seq[j]: the directions of the kept points before it and of the points from
  // seq[j] on (each from the coordinate-wise medians of two halves of up to four points, so that one stray
  // among them does not turn it), and the step between them.
  const auto gap = [&](std::size_t j) {
    const std::size_t before = std::min(kept.size(), kGapRun) / 2, after = std::min(m - j, kGapRun) / 2;
    if (before < 2 || after < 2) return false;
    const std::size_t* back = kept.data() + kept.size() - 2 * before;
    const Vec3 b1 = median_point(points, {back, before}), b2 = median_point(points, {back + before, before});
    const Vec3 a1 = median_point(points, {seq.data() + j, after});
    const Vec3 a2 = median_point(points, {seq.data() + j + after, after});
    const Vec3 step = a1 - b2;
    if (angle_cosine(b2 - b1, step) < kGapCosine || angle_cosine(step, a2 - a1) < kGapCosine) return false;
    const std::size_t a = kept.back(), b = seq[j];
    const Vec3 seg = points[b] - points[a];
    const double l2 = norm_squared(seg), r = std::max(tree.radius[a], tree.radius[b]);
    std::size_t inside = 0;
    for (const std::size_t c : seq) {
      const Vec3 d = points[c] - points[a];
      const double f = std::clamp(dot(d, seg) / l2, 0.0, 1.0);
      if (norm(d - f * seg) < r && distance(points[c], points[a]) > 2.0 * r &&
          distance(points[c], points[b]) > 2.0 * r && ++inside > kMaxDetour)
        return false;
    }
    return true;
  };
  // The start: the first point from which two local steps follow; the ones before it are a detour.
  std::size_t k = 0;
  while (k <= kMaxDetour && !(k + 2 < m && local(seq[k], seq[k + 1]) && local(seq[k + 1], seq[k + 2]))) ++k;
  if (k > kMaxDetour) return false;
  for (std::size_t j = 0; j < k; ++j) suspect[seq[j]] = 1;
  detours += k;
  kept.push_back(seq[k]);
  while (k + 1 < m) {
    std::size_t next = m;  // where the order goes on
    for (std::size_t skip = 0; skip <= kMaxDetour && k + 1 + skip < m && next == m; ++skip)
      if (local(seq[k], seq[k + 1 + skip])) next = k + 1 + skip;
    if (next == m)
      for (std::size_t skip = 0; skip <= kMaxDetour && k + 1 + skip < m && next == m; ++skip)
        if (gap(k + 1 + skip)) {
          next = k + 1 + skip;
          if (++gaps > 1 + n / 100) return false;
        }
    if (next == m) {
      if (m - 1 - k > kMaxDetour) return false;
      next = m;  // the last one to three points: a detour at the end
    }
    for (std::size_t j = k + 1; j < next; ++j) suspect[seq[j]] = 1;
    detours += next - k - 1;
    if (next == m) break;
    k = next;
    kept.push_back(seq[k]);
  }
  return detours * 10 <= n && gaps <= 1 + n / 100;
}

}  // namespace

const char* order_source_name(OrderSource source) noexcept {
  switch (source) {
    case OrderSource::Given:
      return "given";
    case OrderSource::File:
      return "file";
    case OrderSource::SpanningTree:
      return "spanning-tree";
  }
  return "spanning-tree";
}

PointOrder order_along_curve(std::span<const Vec3> points, const PointOrderOptions& options) {
  options.validate();
  check_points(points);
  const std::size_t n = points.size();
  const Tree tree = build_tree(points, options);
  PointOrder out;
  out.isolated = tree.isolated;
  out.path_length = tree.path_s.back();
  std::vector<double> key(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t at = tree.attach[i];
    if (at == kNone) at = tree.attach[nearest_attached(points, tree, i)];
    key[i] = out.path_length > 0.0 ? tree.path_s[at] / out.path_length : 0.0;
  }
  out.key = std::move(key);
  out.order.resize(n);
  std::iota(out.order.begin(), out.order.end(), std::size_t{0});
  std::stable_sort(out.order.begin(), out.order.end(),
                   [&](std::size_t x, std::size_t y) { return out.key[x] < out.key[y]; });
  return out;
}

namespace {

// σ from scaled residuals: 1.4826 × median (planar) or median / 1.1774 (space, Rayleigh).
double sigma_of(std::vector<double>& scaled, bool planar) {
  if (scaled.empty()) return 0.0;
  const auto mid = scaled.begin() + static_cast<std::ptrdiff_t>(scaled.size() / 2);
  std::nth_element(scaled.begin(), mid, scaled.end());
  // |N(0, σ)| has median 0.6745 σ; the norm of two N(0, σ) has median 1.1774 σ.
  return planar ? 1.4826 * *mid : *mid / 1.1774;
}

// Wide windows for noise at or above the spacing (where chord lengths of neighbours are noise): the
// `width` points around each one in `order`, in their principal-axis frame, a quadratic in the axial
// coordinate fitted to each transverse coordinate, the point's transverse residual / √(1 − leverage).
double noise_in_wide_windows(std::span<const Vec3> points, std::span<const std::size_t> order, bool closed,
                             std::size_t width, bool planar) {
  const std::size_t n = order.size();
  const std::size_t half = width / 2;
  std::vector<double> scaled;
  const std::size_t stride = std::max<std::size_t>(1, n / 2000);  // a sample of the points suffices
  for (std::size_t k = 0; k < n; k += stride) {
    const std::size_t lo = closed ? (k + n - half) % n : (k < half ? 0 : std::min(k - half, n - width));
    Vec3 mean{};
    for (std::size_t j = 0; j < width; ++j) mean += points[order[(lo + j) % n]];
    mean = (1.0 / static_cast<double>(width)) * mean;
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (std::size_t j = 0; j < width; ++j) {
      const Vec3 q = points[order[(lo + j) % n]] - mean;
      const Eigen::Vector3d d(q.x, q.y, q.z);
      cov += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    const Eigen::Vector3d axis = eig.eigenvectors().col(2);
    Eigen::Matrix3d xtx = Eigen::Matrix3d::Zero();
    Eigen::Matrix3d xty = Eigen::Matrix3d::Zero();
    Eigen::Vector3d xc = Eigen::Vector3d::Zero(), yc = Eigen::Vector3d::Zero();
    for (std::size_t j = 0; j < width; ++j) {
      const Vec3 q = points[order[(lo + j) % n]] - mean;
      const Eigen::Vector3d d(q.x, q.y, q.z);
      const double tau = d.dot(axis);
      const Eigen::Vector3d x(1.0, tau, tau * tau);
      const Eigen::Vector3d across = d - tau * axis;
      xtx += x * x.transpose();
      xty += x * across.transpose();
      if (order[(lo + j) % n] == order[k]) {
        xc = x;
        yc = across;
      }
    }
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(xtx);
    if (ldlt.info() != Eigen::Success) continue;
    const double leverage = xc.dot(ldlt.solve(xc));
    if (!(leverage < 1.0 - 1e-9)) continue;
    const Eigen::Vector3d r = yc - (ldlt.solve(xty)).transpose() * xc;
    const double value = r.norm() / std::sqrt(1.0 - leverage);
    if (std::isfinite(value)) scaled.push_back(value);
  }
  return sigma_of(scaled, planar);
}

}  // namespace

double estimate_noise(std::span<const Vec3> points, std::span<const std::size_t> order, bool closed) {
  constexpr std::size_t kHalf = 3;  // 7-point windows
  constexpr std::size_t kWidth = 2 * kHalf + 1;
  const std::size_t n = order.size();
  if (n < kWidth) return 0.0;
  bool planar = true;
  for (const Vec3& p : points) planar = planar && p.z == 0.0;
  std::vector<double> scaled;
  scaled.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    // The window: kHalf on each side, wrapped (closed) or shifted inside (open).
    std::size_t lo = 0;
    if (closed) {
      lo = (k + n - kHalf) % n;
    } else {
      lo = k < kHalf ? 0 : std::min(k - kHalf, n - kWidth);
    }
    std::array<Vec3, kWidth> w;
    std::size_t centre = 0;
    for (std::size_t j = 0; j < kWidth; ++j) {
      w[j] = points[order[(lo + j) % n]];
      if (order[(lo + j) % n] == order[k]) centre = j;
    }
    // A cubic in the local chord length τ (centred on the window's middle) fitted to each
    // coordinate by least squares; the residual across the fitted curve's tangent at the point.
    std::array<double, kWidth> tau{};
    for (std::size_t j = 1; j < kWidth; ++j) tau[j] = tau[j - 1] + distance(w[j - 1], w[j]);
    const double mid = tau[kHalf], scale = tau.back() > 0.0 ? tau.back() : 1.0;
    Eigen::Matrix<double, kWidth, 4> x;
    Eigen::Matrix<double, kWidth, 3> y;
    for (std::size_t j = 0; j < kWidth; ++j) {
      const double v = (tau[j] - mid) / scale;
      const auto r = static_cast<Eigen::Index>(j);
      x(r, 0) = 1.0;
      x(r, 1) = v;
      x(r, 2) = v * v;
      x(r, 3) = v * v * v;
      y(r, 0) = w[j].x;
      y(r, 1) = w[j].y;
      y(r, 2) = w[j].z;
    }
    const Eigen::Matrix4d xtx = x.transpose() * x;
    const Eigen::LDLT<Eigen::Matrix4d> ldlt(xtx);
    if (ldlt.info() != Eigen::Success) continue;
    const Eigen::Matrix<double, 4, 3> coef = ldlt.solve(x.transpose() * y);
    const auto c = static_cast<Eigen::Index>(centre);
    const Eigen::RowVector4d xc = x.row(c);
    const double leverage = xc * ldlt.solve(xc.transpose());
    if (!(leverage < 1.0 - 1e-9)) continue;
    const double v = xc(1);
    const Eigen::RowVector4d dxc(0.0, 1.0, 2.0 * v, 3.0 * v * v);
    Eigen::RowVector3d tangent = dxc * coef;
    const double tn = tangent.norm();
    if (!(tn > 0.0)) continue;
    tangent /= tn;
    Eigen::RowVector3d r = y.row(c) - xc * coef;
    r -= r.dot(tangent) * tangent;
    const double value = r.norm() / std::sqrt(1.0 - leverage);
    if (std::isfinite(value)) scaled.push_back(value);
  }
  double sigma = sigma_of(scaled, planar);
  // Noise at or above a fifth of the spacing makes neighbours' chord lengths noise: the windows then
  // widen until they span about 20 σ along the curve, twice. The spacing along the curve is the length
  // of the polyline through the means of consecutive blocks of 21 points, over the point count.
  constexpr std::size_t kBlock = 21;
  if (n >= 2 * kBlock) {
    std::vector<Vec3> means;
    for (std::size_t b = 0; b + kBlock <= n; b += kBlock) {
      Vec3 sum{};
      for (std::size_t j = 0; j < kBlock; ++j) sum += points[order[b + j]];
      means.push_back((1.0 / static_cast<double>(kBlock)) * sum);
    }
    double length = 0.0;
    for (std::size_t b = 1; b < means.size(); ++b) length += distance(means[b - 1], means[b]);
    const double spacing = length / static_cast<double>(kBlock * (means.size() - 1));
    for (int pass = 0; pass < 2 && spacing > 0.0 && sigma > 0.2 * spacing; ++pass) {
      const auto want = static_cast<std::size_t>(std::ceil(10.0 * sigma / spacing));
      const std::size_t width = std::min<std::size_t>(2 * std::clamp<std::size_t>(want, 4, 150) + 1, n);
      sigma = std::max(sigma, noise_in_wide_windows(points, order, closed, width, planar));
    }
  }
  return sigma;
}

CurveOrder order_points(std::span<const Vec3> points, bool given, const PointOrderOptions& options) {
  options.validate();
  check_points(points);
  const std::size_t n = points.size();
  const Tree tree = build_tree(points, options);
  std::vector<char> suspect(n, 0);
  for (const std::size_t i : tree.isolated) suspect[i] = 1;
  auto near = [&](std::size_t a, std::size_t b) {
    return distance(points[a], points[b]) <= 2.0 * std::max(tree.radius[a], tree.radius[b]);
  };
  CurveOrder out;

  // The file order: consistent when the non-isolated points follow one another, detours and gaps aside.
  bool file_order = given;
  std::vector<std::size_t> seq;
  if (!given) {
    file_order = file_order_is_consistent(points, tree, suspect);
    if (!file_order)
      for (std::size_t i = 0; i < n; ++i) suspect[i] = 0;
    for (const std::size_t i : tree.isolated) suspect[i] = 1;
  }

  std::vector<double> t(n, 0.0);
  if (file_order) {
    out.source = given ? OrderSource::Given : OrderSource::File;
    std::vector<std::size_t> identity(n);
    std::iota(identity.begin(), identity.end(), std::size_t{0});
    seq.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (!suspect[i]) seq.push_back(i);
    if (seq.size() < 3) {
      seq = identity;
      std::fill(suspect.begin(), suspect.end(), 0);
    }
    out.noise = estimate_noise(points, seq, false);
    // Chord lengths, of a running mean over five points when the noise is large against the spacing.
    std::vector<double> steps;
    for (std::size_t k = 0; k + 1 < seq.size(); ++k) steps.push_back(distance(points[seq[k]], points[seq[k + 1]]));
    std::vector<double> sorted = steps;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    const double median_step = sorted[sorted.size() / 2];
    std::vector<Vec3> q(seq.size());
    const std::size_t half = out.noise > 0.3 * median_step ? 2 : 0;
    for (std::size_t k = 0; k < seq.size(); ++k) {
      const std::size_t lo = k >= half ? k - half : 0, hi = std::min(seq.size() - 1, k + half);
      Vec3 sum{};
      for (std::size_t j = lo; j <= hi; ++j) sum += points[seq[j]];
      q[k] = (1.0 / static_cast<double>(hi - lo + 1)) * sum;
    }
    std::vector<double> s(seq.size(), 0.0);
    for (std::size_t k = 1; k < seq.size(); ++k) s[k] = s[k - 1] + distance(q[k - 1], q[k]);
    // Closed: the ends near each other and the directions there within 60° of each other.
    const std::size_t lead = std::max<std::size_t>(3, seq.size() / 50);
    const std::size_t f = seq.front(), l = seq.back();
    if (seq.size() > 4 * lead && near(f, l)) {
      const Vec3 start_dir = q[lead] - q[0], end_dir = q.back() - q[q.size() - 1 - lead];
      out.closed = angle_cosine(start_dir, end_dir) > kSmoothJoinCosine;
    }
    const double total = s.back() + (out.closed ? distance(q.back(), q.front()) : 0.0);
    if (!(total > 0.0)) throw Error(Errc::CoincidentPoints, "all points coincide", ErrorWhere{.field = "points"});
    for (std::size_t k = 0; k < seq.size(); ++k) t[seq[k]] = s[k] / total;
    // Suspects take the parameter of the sequence point before them in the file.
    double last = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (suspect[i])
        t[i] = last;
      else
        last = t[i];
    }
  } else {
    out.source = OrderSource::SpanningTree;
    // The path smoothed by a running mean over five nodes; every point projected on it near the node
    // its branch hangs from, the end segments extended.
    const std::size_t len = tree.path.size();
    std::vector<Vec3> sm(len);
    for (std::size_t j = 0; j < len; ++j) {
      const std::size_t lo = j >= 2 ? j - 2 : 0, hi = std::min(len - 1, j + 2);
      Vec3 sum{};
      for (std::size_t k = lo; k <= hi; ++k) sum += points[tree.path[k]];
      sm[j] = (1.0 / static_cast<double>(hi - lo + 1)) * sum;
    }
    std::vector<double> s(len, 0.0);
    for (std::size_t j = 1; j < len; ++j) s[j] = s[j - 1] + distance(sm[j - 1], sm[j]);
    constexpr std::size_t kWindow = 12;
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t at = tree.attach[i];
      if (at == kNone) at = tree.attach[nearest_attached(points, tree, i)];
      if (len < 2) {
        t[i] = 0.0;
        continue;
      }
      const std::size_t lo = at > kWindow ? at - kWindow : 0, hi = std::min(len - 2, at + kWindow);
      double best = std::numeric_limits<double>::infinity(), arc = s[at];
      for (std::size_t j = lo; j <= hi; ++j) {
        const Vec3 seg = sm[j + 1] - sm[j];
        const double l2 = norm_squared(seg);
        double f = l2 > 0.0 ? dot(points[i] - sm[j], seg) / l2 : 0.0;
        if (!(j == 0 && f < 0.0) && !(j + 2 == len && f > 1.0)) f = std::clamp(f, 0.0, 1.0);
        const double d = norm_squared(sm[j] + f * seg - points[i]);
        if (d < best) {
          best = d;
          arc = s[j] + f * std::sqrt(l2);
        }
      }
      t[i] = arc;
    }
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < n; ++i)
      if (!suspect[i]) {
        lo = std::min(lo, t[i]);
        hi = std::max(hi, t[i]);
      }
    if (!(hi > lo)) throw Error(Errc::CoincidentPoints, "all points coincide", ErrorWhere{.field = "points"});
    // Closed: the path's ends near each other (the tree cut the loop open there) and its end
    // directions within 60°.
    const double gap = distance(sm.front(), sm.back());
    std::vector<double> radii = tree.radius;
    std::nth_element(radii.begin(), radii.begin() + static_cast<std::ptrdiff_t>(n / 2), radii.end());
    const double typical = radii[n / 2];
    const std::size_t lead = std::max<std::size_t>(3, len / 50);
    if (len > 4 * lead && gap <= 4.0 * typical && gap * 10.0 < s.back()) {
      const Vec3 start_dir = sm[lead] - sm[0], end_dir = sm.back() - sm[len - 1 - lead];
      out.closed = angle_cosine(start_dir, end_dir) > kSmoothJoinCosine;
    }
    const double span = (hi - lo) + (out.closed ? gap : 0.0);
    for (double& v : t) v = std::clamp((v - lo) / span, 0.0, 1.0);
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return t[x] < t[y]; });
    std::vector<std::size_t> kept;
    for (const std::size_t i : order)
      if (!suspect[i]) kept.push_back(i);
    out.noise = estimate_noise(points, kept.size() >= 3 ? std::span<const std::size_t>(kept) : order, out.closed);
  }
  if (out.closed)
    for (double& v : t) v = std::min(v, std::nextafter(1.0, 0.0));
  out.parameters = std::move(t);
  for (std::size_t i = 0; i < n; ++i)
    if (suspect[i]) out.suspects.push_back(i);
  return out;
}

}  // namespace hula::studies
