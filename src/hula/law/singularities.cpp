// SPDX-License-Identifier: MIT
// Singularity report (see singularities.hpp): one condition law per
// hazardous node, whose roots on [a, b] are the reported points.
#include "hula/law/singularities.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>
#include <unordered_set>

#include "hula/core/error.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/detail/short_print.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/tape.hpp"

namespace hula::law {

using detail::short_print;

const char* singularity_kind_name(SingularityKind kind) {
  switch (kind) {
    case SingularityKind::DivisionByZero:
      return "DivisionByZero";
    case SingularityKind::SqrtBoundary:
      return "SqrtBoundary";
    case SingularityKind::LogBoundary:
      return "LogBoundary";
    case SingularityKind::PowerBase:
      return "PowerBase";
    case SingularityKind::InverseTrigBound:
      return "InverseTrigBound";
    case SingularityKind::TanPole:
      return "TanPole";
    case SingularityKind::Atan2Origin:
      return "Atan2Origin";
    case SingularityKind::NormalizeZero:
      return "NormalizeZero";
    case SingularityKind::NormKink:
      return "NormKink";
    case SingularityKind::AbsKink:
      return "AbsKink";
    case SingularityKind::SignJump:
      return "SignJump";
    case SingularityKind::MinMaxSwitch:
      return "MinMaxSwitch";
    case SingularityKind::PiecewiseSwitch:
      return "PiecewiseSwitch";
    case SingularityKind::ComparisonJump:
      return "ComparisonJump";
    case SingularityKind::CurveKnot:
      return "CurveKnot";
    case SingularityKind::CurveDomainEnd:
      return "CurveDomainEnd";
  }
  return "?";
}

void SingularityOptions::validate() const {
  roots.validate();
  if (samples < 2)
    throw Error(Errc::InvalidOption, "SingularityOptions::samples must be >= 2, got " + std::to_string(samples),
                ErrorWhere{.field = "samples"});
}

namespace {

struct Condition {
  Law law;  // scalar: the points are its roots
  SingularityKind kind;
  Law source;
};

/// The condition laws of one node (empty for smooth, total operations).
void conditions(const Law& e, std::vector<Condition>& out) {
  const Node n = e.node();  // a copy: building nodes may reallocate the node array
  Context ctx = e.context();
  auto add = [&](const Law& g, SingularityKind k) {
    if (!g.is_constant()) out.push_back({g, k, e});
  };
  switch (n.op) {
    case Op::Div:
      add(e.arg(1), SingularityKind::DivisionByZero);
      break;
    case Op::Sqrt:
      add(e.arg(0), SingularityKind::SqrtBoundary);
      break;
    case Op::Log:
      add(e.arg(0), SingularityKind::LogBoundary);
      break;
    case Op::Pow: {
      const Law b = e.arg(1);
      const bool nonneg_int = b.is_constant() && b.node().value >= 0 && b.node().value == std::floor(b.node().value);
      if (!nonneg_int) add(e.arg(0), SingularityKind::PowerBase);
      break;
    }
    case Op::Asin:
    case Op::Acos:
      add(e.arg(0) - 1.0, SingularityKind::InverseTrigBound);
      add(e.arg(0) + 1.0, SingularityKind::InverseTrigBound);
      break;
    case Op::Tan:
      add(cos(e.arg(0)), SingularityKind::TanPole);
      break;
    case Op::Atan2:
      add(e.arg(0) * e.arg(0) + e.arg(1) * e.arg(1), SingularityKind::Atan2Origin);
      break;
    case Op::Normalize:
      add(e.arg(0).dimension() == 1 ? e.arg(0) : dot(e.arg(0), e.arg(0)), SingularityKind::NormalizeZero);
      break;
    case Op::Norm:
      add(e.arg(0).dimension() == 1 ? e.arg(0) : dot(e.arg(0), e.arg(0)), SingularityKind::NormKink);
      break;
    case Op::Abs:
      add(e.arg(0), SingularityKind::AbsKink);
      break;
    case Op::Sign:
      add(e.arg(0), SingularityKind::SignJump);
      break;
    case Op::Min:
    case Op::Max:
      add(e.arg(0) - e.arg(1), SingularityKind::MinMaxSwitch);
      break;
    case Op::Less:
    case Op::LessEqual:
      add(e.arg(0) - e.arg(1), SingularityKind::ComparisonJump);
      break;
    case Op::Piecewise: {
      const Law c = e.arg(0);
      if (c.op() == Op::Less || c.op() == Op::LessEqual)
        add(c.arg(0) - c.arg(1), SingularityKind::PiecewiseSwitch);
      else
        add(c, SingularityKind::PiecewiseSwitch);
      break;
    }
    case Op::Curve: {
      const auto& curve = ctx.curve_at(n.index);
      const auto bp = curve.knots().breakpoints();
      for (std::size_t i = 1; i + 1 < bp.size(); ++i) add(e.arg(0) - bp[i], SingularityKind::CurveKnot);
      add(e.arg(0) - bp.front(), SingularityKind::CurveDomainEnd);
      add(e.arg(0) - bp.back(), SingularityKind::CurveDomainEnd);
      break;
    }
    default:
      break;
  }
}

}  // namespace

SingularityReport singularities(const Law& f, std::string_view parameter, double a, double b,
                                const SingularityOptions& options) {
  options.validate();
  if (!f.valid()) throw Error(Errc::InvalidArgument, "singularities: empty law");
  if (!(std::isfinite(a) && std::isfinite(b) && a < b))
    throw Error(Errc::InvalidArgument, "singularities: needs a finite interval a < b, got [" + format_number(a) + ", " +
                                           format_number(b) + "]");
  SingularityReport report;
  // every node once (iterative: deep DAGs cannot overflow the stack)
  std::vector<Condition> conds;
  std::unordered_set<NodeId> seen;
  std::vector<Law> stack{f};
  while (!stack.empty()) {
    const Law e = stack.back();
    stack.pop_back();
    if (!seen.insert(e.id()).second) continue;
    conditions(e, conds);
    for (std::size_t i = 0; i < e.node().arity; ++i) stack.push_back(e.arg(i));
  }
  for (const Condition& c : conds) {
    // A condition that changes sign through a jump of its own (piecewise(sign(t − 1), …)) still
    // switches there: its unresolved sign changes are points too.
    const RootReport found = find_roots(c.law, parameter, a, b, options.roots);
    for (double t : found.roots) report.points.push_back({t, c.kind, short_print(c.source)});
    for (double t : found.unresolved) report.points.push_back({t, c.kind, short_print(c.source)});
  }
  std::sort(report.points.begin(), report.points.end(), [](const Singularity& x, const Singularity& y) {
    return x.t != y.t ? x.t < y.t : static_cast<int>(x.kind) < static_cast<int>(y.kind);
  });
  // One entry per point and kind (the same zero can come from several equal conditions); a
  // comparison that is the condition of a piecewise switching at the same point is that switch.
  std::vector<Singularity> unique;
  for (auto& s : report.points) {
    bool dup = false;
    for (auto it = unique.rbegin(); it != unique.rend() && s.t - it->t <= 1e-12 * std::max(1.0, std::fabs(s.t)); ++it)
      dup = dup || it->kind == s.kind ||
            (s.kind == SingularityKind::ComparisonJump && it->kind == SingularityKind::PiecewiseSwitch);
    if (!dup) unique.push_back(std::move(s));
  }
  report.points = std::move(unique);

  // undefined intervals by sampling the compiled law
  const std::string in[1] = {std::string(parameter)};
  const Law outs[1] = {f};
  const Tape tape = Tape::compile(outs, in);
  Workspace w = tape.make_workspace();
  std::vector<double> out(tape.output_count());
  auto defined = [&](double t) { return tape.evaluate(std::span<const double>(&t, 1), out, w); };
  auto boundary = [&](double good, double bad) {  // bisection between a defined and an undefined parameter
    for (int it = 0; it < 200 && std::fabs(bad - good) > 1e-12 * std::max(1.0, std::fabs(good)); ++it) {
      const double m = 0.5 * (good + bad);
      (defined(m) ? good : bad) = m;
    }
    return bad;
  };
  const std::size_t n = options.samples;
  double prev_t = a;
  bool prev_ok = defined(a);
  double start = a;
  for (std::size_t i = 1; i <= n; ++i) {
    const double t = i == n ? b : a + (b - a) * static_cast<double>(i) / static_cast<double>(n);
    const bool ok = defined(t);
    if (prev_ok && !ok) start = boundary(prev_t, t);
    if (!prev_ok && ok) report.undefined.push_back({start, boundary(t, prev_t)});
    prev_t = t;
    prev_ok = ok;
  }
  if (!prev_ok) report.undefined.push_back({start, b});
  return report;
}

namespace {
const char* undefined_reason(Op op) {
  switch (op) {
    case Op::Div:
      return "division by zero";
    case Op::Sqrt:
      return "sqrt of a negative number";
    case Op::Log:
      return "log of a number <= 0";
    case Op::Pow:
      return "0 to a negative power, or a negative base to a non-integer power";
    case Op::Asin:
      return "asin of a number outside [-1, 1]";
    case Op::Acos:
      return "acos of a number outside [-1, 1]";
    case Op::Atan2:
      return "atan2(0, 0)";
    case Op::Normalize:
      return "normalize of a zero vector";
    case Op::Norm:
      return "norm of a zero vector";
    case Op::Curve:
      return "parameter outside the NURBS curve's domain";
    default:
      return "undefined operation";
  }
}
}  // namespace

namespace {

/// Every node reachable from f, arguments before the node, evaluated at t.
struct AllValues {
  std::vector<Law> order;
  std::unordered_map<NodeId, std::size_t> offset;  // first component of a node in out
  std::vector<double> out;
  [[nodiscard]] bool finite(NodeId id, int dimension) const {
    const std::size_t k = offset.at(id);
    for (int c = 0; c < dimension; ++c)
      if (!std::isfinite(out[k + static_cast<std::size_t>(c)])) return false;
    return true;
  }
  [[nodiscard]] bool defined(NodeId id, int dimension) const {
    const std::size_t k = offset.at(id);
    for (int c = 0; c < dimension; ++c)
      if (std::isnan(out[k + static_cast<std::size_t>(c)])) return false;
    return true;
  }
  [[nodiscard]] double first(NodeId id) const { return out[offset.at(id)]; }
};

AllValues evaluate_all(const Law& f, std::string_view parameter, double t) {
  AllValues v;
  std::unordered_set<NodeId> seen;
  std::vector<std::pair<Law, bool>> stack{{f, false}};
  while (!stack.empty()) {
    auto [e, expanded] = stack.back();
    stack.pop_back();
    if (expanded) {
      v.order.push_back(e);
      continue;
    }
    if (!seen.insert(e.id()).second) continue;
    stack.push_back({e, true});
    for (std::size_t i = 0; i < e.node().arity; ++i)
      if (!seen.count(e.node().args[i])) stack.push_back({e.arg(i), false});
  }
  const std::string in[1] = {std::string(parameter)};
  const Tape tape = Tape::compile(v.order, in);
  v.out.resize(tape.output_count());
  (void)tape.evaluate(std::span<const double>(&t, 1), v.out);
  std::size_t k = 0;
  for (const Law& e : v.order) {
    v.offset[e.id()] = k;
    k += static_cast<std::size_t>(e.dimension());
  }
  return v;
}

/// Descends from f through arguments failing `bad` (into the selected branch of a piecewise whose
/// condition is fine) to the innermost failing node whose arguments are all fine.
template <class Bad>
Law innermost(const Law& f, const AllValues& v, Bad bad) {
  Law e = f;
  for (;;) {
    const Node n = e.node();
    std::optional<Law> next;
    if (n.op == Op::Piecewise && !bad(e.arg(0))) {
      next = v.first(n.args[0]) != 0.0 ? e.arg(1) : e.arg(2);
    } else {
      for (std::size_t i = 0; i < n.arity && !next; ++i)
        if (bad(e.arg(i))) next = e.arg(i);
    }
    if (!next || !bad(*next)) return e;
    e = *next;
  }
}

}  // namespace

std::optional<UndefinedCause> explain_undefined(const Law& f, std::string_view parameter, double t) {
  if (!f.valid()) throw Error(Errc::InvalidArgument, "explain_undefined: empty law");
  const AllValues v = evaluate_all(f, parameter, t);
  // Other nodes may be undefined in an unselected piecewise branch: only f itself decides.
  if (v.defined(f.id(), f.dimension())) return std::nullopt;
  const Law e = innermost(f, v, [&v](const Law& a) { return !v.defined(a.id(), a.dimension()); });
  return UndefinedCause{short_print(e), undefined_reason(e.node().op)};
}

std::optional<NonFiniteCause> explain_non_finite(const Law& f, std::string_view parameter, double t) {
  if (!f.valid()) throw Error(Errc::InvalidArgument, "explain_non_finite: empty law");
  const AllValues v = evaluate_all(f, parameter, t);
  if (v.finite(f.id(), f.dimension())) return std::nullopt;
  const Law e = innermost(f, v, [&v](const Law& a) { return !v.finite(a.id(), a.dimension()); });
  if (v.defined(e.id(), e.dimension()))
    return NonFiniteCause{true, short_print(e), "overflow (the value exceeds 1.8e308)"};
  return NonFiniteCause{false, short_print(e), undefined_reason(e.node().op)};
}

namespace {

const char* kink_reason(SingularityKind kind) {
  switch (kind) {
    case SingularityKind::AbsKink:
      return "abs has a kink where its argument changes sign";
    case SingularityKind::SignJump:
      return "sign jumps where its argument changes sign";
    case SingularityKind::MinMaxSwitch:
      return "min/max switches between its arguments (a kink)";
    case SingularityKind::ComparisonJump:
      return "a comparison changes value (a jump)";
    case SingularityKind::PiecewiseSwitch:
      return "a piecewise law switches branch (a join)";
    case SingularityKind::NormKink:
      return "the norm of a vector through zero has a kink";
    case SingularityKind::CurveKnot:
      return "a NURBS curve's derivative of this order is not continuous at the knot";
    default:
      return "not differentiable";
  }
}

bool is_kink(SingularityKind kind) {
  switch (kind) {
    case SingularityKind::AbsKink:
    case SingularityKind::SignJump:
    case SingularityKind::MinMaxSwitch:
    case SingularityKind::ComparisonJump:
    case SingularityKind::PiecewiseSwitch:
    case SingularityKind::NormKink:
      return true;
    default:
      return false;  // undefined points are NaN and reported as such; knots are filtered below
  }
}

/// The kink conditions of every node of e: those of conditions() that break differentiability
/// without making the value undefined, and NURBS knots where the leaf's order reaches the
/// curve's continuity (the leaf of order o is differentiable at a knot of multiplicity m when
/// o < degree − m).
std::vector<Condition> kink_conditions(const Law& e0) {
  std::vector<Condition> out;
  std::unordered_set<NodeId> seen;
  std::vector<Law> stack{e0};
  while (!stack.empty()) {
    const Law e = stack.back();
    stack.pop_back();
    if (!seen.insert(e.id()).second) continue;
    const Node n = e.node();
    if (n.op == Op::Curve) {
      Context ctx = e.context();
      const auto& curve = ctx.curve_at(n.index);
      const auto bp = curve.knots().breakpoints();
      for (std::size_t i = 1; i + 1 < bp.size(); ++i) {
        const int m = static_cast<int>(curve.knots().multiplicity(bp[i]));
        if (static_cast<int>(n.order) >= curve.degree() - m)
          out.push_back({e.arg(0) - bp[i], SingularityKind::CurveKnot, e});
      }
    } else {
      std::vector<Condition> all;
      conditions(e, all);
      for (auto& c : all)
        if (is_kink(c.kind)) out.push_back(std::move(c));
    }
    for (std::size_t i = 0; i < n.arity; ++i) stack.push_back(e.arg(i));
  }
  return out;
}

}  // namespace

std::optional<NonSmoothPoint> nonsmooth_at(const Law& f, std::string_view parameter, double t, int max_order) {
  if (!f.valid()) throw Error(Errc::InvalidArgument, "nonsmooth_at: empty law");
  if (max_order < 0) throw Error(Errc::InvalidArgument, "nonsmooth_at: max_order must be >= 0");
  if (max_order == 0) return std::nullopt;
  const std::vector<Law> laws = derivatives(f, parameter, max_order - 1);
  const std::string in[1] = {std::string(parameter)};
  const double scale = kKinkTolerance * std::max(1.0, std::fabs(t));
  for (int k = 0; k < max_order; ++k) {
    const std::vector<Condition> conds = kink_conditions(laws[static_cast<std::size_t>(k)]);
    if (conds.empty()) continue;
    std::vector<Law> outs;  // g, g' per condition
    for (const Condition& c : conds) {
      outs.push_back(c.law);
      outs.push_back(derivative(c.law, parameter, 1));
    }
    const Tape tape = Tape::compile(outs, in);
    std::vector<double> v(tape.output_count());
    (void)tape.evaluate(std::span<const double>(&t, 1), v);
    for (std::size_t i = 0; i < conds.size(); ++i) {
      const double g = v[2 * i];
      const double dg = v[2 * i + 1];
      if (g == 0.0 || std::fabs(g) <= scale * std::fabs(dg))
        return NonSmoothPoint{k + 1, conds[i].kind, short_print(conds[i].source), kink_reason(conds[i].kind)};
    }
  }
  return std::nullopt;
}

}  // namespace hula::law
