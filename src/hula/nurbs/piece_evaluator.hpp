// SPDX-License-Identifier: MIT
// PieceEvaluator: a curve's derivatives without its per-span cache. NurbsCurve builds the Taylor
// coefficients of every span on its first evaluation; for a curve of a million spans that is 180 MB
// and a pass over every span, which one pass along the curve (the arc length) or a few points on it
// (the ends in `hula info`) does not need. This evaluator computes the coefficients of the span it is
// asked about, the same way, into a buffer of its own and evaluates them with the same kernels, so it
// gives the same doubles as NurbsCurve::derivatives. A curve whose cache is built already, or with
// few spans, is evaluated through the cache.
#pragma once

#include <memory>
#include <span>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs {

/// One span's Taylor piece at a time (no allocation after the first). Not thread-safe: one per thread.
class PieceEvaluator {
 public:
  /// Curves with fewer non-empty-or-empty knot spans than this use the curve's cache.
  static constexpr std::size_t kMinSpans = 4096;

  /// @param curve evaluated; it must outlive the evaluator
  explicit PieceEvaluator(const NurbsCurve& curve);
  ~PieceEvaluator();
  PieceEvaluator(const PieceEvaluator&) = delete;
  PieceEvaluator& operator=(const PieceEvaluator&) = delete;

  /// out[i * (order + 1) + k] = C^(k)(ts[i]): the values and errors of
  /// curve.derivatives(ts, order, out) with the default EvalOptions. Parameters in one knot span are
  /// evaluated from that span's piece; anything else goes to the curve (which builds its cache).
  void derivatives(std::span<const double> ts, int order, std::span<Vec3> out);

  /// out[i] = |C'(ts[i])|: the doubles of norm(C'(ts[i])) with C' from derivatives(ts, 1, …), and its
  /// errors. Parameters strictly inside one knot span are evaluated together by the SIMD speed kernel
  /// (degrees 2…5: the same operations per lane); anything else goes through derivatives().
  /// @param ts at most 64 parameters
  void speeds(std::span<const double> ts, std::span<double> out);

 private:
  struct State;
  // The piece of the knot span containing t (inside the domain) loaded into the state, with its exact points
  // and span search when `whole`; returns its knot index.
  std::size_t load_span(double t, bool whole);
  const NurbsCurve& curve_;
  std::unique_ptr<State> state_;
};

}  // namespace hula::nurbs
