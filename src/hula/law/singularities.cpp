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
#include "hula/law/parser.hpp"
#include "hula/law/tape.hpp"

namespace hula::law {

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

std::string short_print(const Law& l) {
  std::string s = print(l);
  if (s.size() > 120) s = s.substr(0, 117) + "...";
  return s;
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
    for (double t : roots(c.law, parameter, a, b, options.roots)) {
      report.points.push_back({t, c.kind, short_print(c.source)});
    }
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

std::optional<UndefinedCause> explain_undefined(const Law& f, std::string_view parameter, double t) {
  if (!f.valid()) throw Error(Errc::InvalidArgument, "explain_undefined: empty law");
  // Every reachable node in post-order (arguments before the node), all compiled as outputs.
  std::vector<Law> order;
  std::unordered_set<NodeId> seen;
  std::vector<std::pair<Law, bool>> stack{{f, false}};
  while (!stack.empty()) {
    auto [e, expanded] = stack.back();
    stack.pop_back();
    if (expanded) {
      order.push_back(e);
      continue;
    }
    if (!seen.insert(e.id()).second) continue;
    stack.push_back({e, true});
    for (std::size_t i = 0; i < e.node().arity; ++i)
      if (!seen.count(e.node().args[i])) stack.push_back({e.arg(i), false});
  }
  const std::string in[1] = {std::string(parameter)};
  const Tape tape = Tape::compile(order, in);
  std::vector<double> out(tape.output_count());
  if (tape.evaluate(std::span<const double>(&t, 1), out)) return std::nullopt;
  // Other outputs may be undefined in an unselected piecewise branch: only f itself (the last
  // node of the post-order) decides.
  bool f_defined = true;
  for (std::size_t c = out.size() - static_cast<std::size_t>(f.dimension()); c < out.size(); ++c)
    f_defined = f_defined && !std::isnan(out[c]);
  if (f_defined) return std::nullopt;
  std::unordered_map<NodeId, bool> defined;
  std::size_t k = 0;
  for (const Law& e : order) {
    bool ok = true;
    for (int c = 0; c < e.dimension(); ++c) ok = ok && !std::isnan(out[k++]);
    defined[e.id()] = ok;
  }
  std::unordered_map<NodeId, double> first_value;  // first component, for piecewise conditions
  k = 0;
  for (const Law& e : order) {
    first_value[e.id()] = out[k];
    k += static_cast<std::size_t>(e.dimension());
  }
  // Descend from f through undefined arguments (into the selected branch of a piecewise) to the
  // innermost node that is undefined although its arguments are defined.
  Law e = f;
  for (;;) {
    const Node n = e.node();
    std::optional<Law> next;
    if (n.op == Op::Piecewise && defined[n.args[0]]) {
      next = first_value[n.args[0]] != 0.0 ? e.arg(1) : e.arg(2);
    } else {
      for (std::size_t i = 0; i < n.arity && !next; ++i)
        if (!defined[n.args[i]]) next = e.arg(i);
    }
    if (!next || defined[next->id()]) return UndefinedCause{short_print(e), undefined_reason(n.op)};
    e = *next;
  }
}

}  // namespace hula::law
