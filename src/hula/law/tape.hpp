// SPDX-License-Identifier: MIT
// Compiled evaluation of laws: a set of laws (typically a curve law and its
// derivatives) is flattened into one array of scalar instructions over a slot
// array (inputs, constants, temporaries), with common subexpressions shared
// across all outputs, vector operations expanded component-wise and trivial
// scalar identities removed. Evaluation runs the instructions in order with
// no allocation: the slot array lives in a Workspace created once (or in a
// per-thread buffer reused across calls). Batches run block-major: each
// instruction processes Tape::kBlock points before the next one, and sin and
// cos of the same argument are computed together (sincos).
//
// Undefined values (docs: expr.hpp) come out as NaN and are reported by the
// boolean results; ±inf only means overflow. Vector norms are evaluated as
// sqrt(x² + y² + z²) (no scaling: magnitudes above 1e150 overflow).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/expr.hpp"

namespace hula::law {

/// Per-evaluation slot storage of one Tape (constants pre-filled). Not shareable between
/// threads; create one per thread.
class Workspace {
 public:
  Workspace() = default;

 private:
  friend class Tape;
  std::uint64_t tape_id_ = 0;
  std::vector<double> slots_;  // one point
  std::vector<double> block_;  // kBlock points, slot-major (slot k of point j at k * kBlock + j)
};

/// An immutable compiled program computing several laws at once. Thread-safe for concurrent
/// evaluation with one Workspace per thread.
class Tape {
 public:
  /// Compiles `outputs` as functions of the named `inputs`.
  /// @param outputs laws of one context (scalars or vectors); output k occupies dimension() slots
  ///   of the output array, in order
  /// @param inputs parameter names, in the order of the input array
  /// @throws hula::Error(Errc::InvalidArgument) if outputs is empty or mixes contexts, or a law
  ///   uses a parameter that is not an input (named in the message)
  [[nodiscard]] static Tape compile(std::span<const Law> outputs, std::span<const std::string> inputs);

  /// Number of inputs per point.
  [[nodiscard]] std::size_t input_count() const noexcept;
  /// Number of scalar outputs per point (sum of output dimensions).
  [[nodiscard]] std::size_t output_count() const noexcept;
  /// Number of instructions (a measure of cost).
  [[nodiscard]] std::size_t instruction_count() const noexcept;
  /// Number of slots per point (inputs + constants + temporaries).
  [[nodiscard]] std::size_t slot_count() const noexcept;

  /// A workspace for this tape (allocates once).
  [[nodiscard]] Workspace make_workspace() const;

  /// Evaluates one point: outputs[k] for k < output_count().
  /// @returns true when every output is defined (no NaN); undefined outputs are NaN
  /// @throws hula::Error(Errc::InvalidArgument) if a span has the wrong size or the workspace
  ///   belongs to another tape
  bool evaluate(std::span<const double> inputs, std::span<double> outputs, Workspace& workspace) const;
  /// As above with a per-thread workspace (allocation only when a thread first meets a larger tape).
  bool evaluate(std::span<const double> inputs, std::span<double> outputs) const;
  /// Batch: point i reads inputs[i * input_count() …] and writes outputs[i * output_count() …].
  /// No allocation per point.
  /// @param defined empty, or one flag per point set to 1 when all its outputs are defined
  /// @returns the number of points with an undefined output
  /// @throws hula::Error(Errc::InvalidArgument) if the span sizes do not match
  std::size_t evaluate(std::span<const double> inputs, std::span<double> outputs, Workspace& workspace,
                       std::span<std::uint8_t> defined) const;
  /// Batch with a per-thread workspace (allocation only when a thread first meets a larger tape).
  std::size_t evaluate(std::span<const double> inputs, std::span<double> outputs,
                       std::span<std::uint8_t> defined) const;

  /// Points evaluated together by the batch form (instruction-major over a block, so each
  /// instruction is dispatched once per block and its loop vectorises).
  static constexpr std::size_t kBlock = 32;

  /// The compiled program (opaque; defined in tape.cpp).
  struct Program;

 private:
  void check(const Workspace& w) const;
  std::shared_ptr<const Program> program_;
};

/// A one-parameter vector (or scalar) law with its derivatives up to `order`, compiled together:
/// the law counterpart of NurbsCurve::derivatives.
class CurveEvaluator {
 public:
  /// @param law a law of `parameter` only (other parameters are an error)
  /// @param parameter the curve parameter name, e.g. "t"
  /// @param order highest derivative, 0 … 16
  /// @throws hula::Error(Errc::InvalidArgument) if order is out of range or the law uses another parameter
  CurveEvaluator(const Law& law, const std::string& parameter, int order);

  [[nodiscard]] int order() const noexcept { return order_; }
  [[nodiscard]] int dimension() const noexcept { return dimension_; }
  [[nodiscard]] const Tape& tape() const noexcept { return tape_; }
  /// {C(t), C'(t), …, C^(order)(t)} into out (order + 1 vectors; unused coordinates 0 for scalars and
  /// 2-vectors). Per-thread workspace; no allocation.
  /// @returns true when every value is defined (NaN components otherwise)
  bool derivatives(double t, std::span<Vec3> out) const;
  /// Batch: out[i * (order + 1) + k] = C^(k)(ts[i]). @returns the number of undefined points.
  std::size_t derivatives(std::span<const double> ts, std::span<Vec3> out) const;
  /// Position only, allocating convenience form.
  [[nodiscard]] std::vector<Vec3> derivatives(double t) const;

 private:
  Tape tape_;
  int order_;
  int dimension_;
};

}  // namespace hula::law
