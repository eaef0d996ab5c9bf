// SPDX-License-Identifier: MIT
// Compilation of law DAGs to a flat scalar instruction tape, and its
// interpreter. Compilation walks the DAG once in post-order (iteratively, so
// deep graphs cannot overflow the stack), gives every node the slots of its
// components, and emits scalar instructions through a local value-numbering
// table (common subexpressions across all outputs share one slot), folding
// constant operands with the very functions the interpreter runs.
#include "hula/law/tape.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "hula/core/error.hpp"
#include "hula/law/detail/graph.hpp"
#include "hula/law/detail/scalar_ops.hpp"

namespace hula::law {

using namespace detail;

namespace {

enum class Code : std::uint8_t {
  Neg,
  Add,
  Sub,
  Mul,
  Div,
  Pow,
  PowI,
  Sqrt,
  Exp,
  Log,
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Atan2,
  Sinh,
  Cosh,
  Tanh,
  Abs,
  Sign,
  Min,
  Max,
  Less,
  LessEq,
  Select,
  Curve,
  SinCos,  // out = sin(a), b = the slot receiving cos(a)
};

struct Instr {
  Code code;
  std::uint32_t out;
  std::uint32_t a;
  std::uint32_t b;  // PowI: exponent (as int32); Curve: curve index
  std::uint32_t c;  // Curve: derivative order
};

std::atomic<std::uint64_t> g_next_tape_id{1};

/// Largest NURBS derivative order a tape evaluates (stack buffer size).
constexpr std::uint32_t kMaxCurveOrder = 31;

}  // namespace

struct Tape::Program {
  std::uint64_t id = 0;
  std::size_t inputs = 0;
  std::vector<Instr> code;
  std::vector<double> initial;  // slot values at start: constants filled, the rest 0
  std::vector<std::uint32_t> outputs;
  std::vector<nurbs::NurbsCurve> curves;
};

namespace {

struct KeyHash {
  std::size_t operator()(const std::array<std::uint32_t, 4>& k) const noexcept {
    std::uint64_t h = 1469598103934665603ULL;
    for (auto v : k) h = (h ^ v) * 1099511628211ULL;
    return static_cast<std::size_t>(h);
  }
};

class Compiler {
 public:
  Compiler(Tape::Program& p, const Graph& g) : p_(p), g_(g) {}

  std::uint32_t constant(double v) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    if (auto it = consts_.find(bits); it != consts_.end()) return it->second;
    const auto s = static_cast<std::uint32_t>(p_.initial.size());
    p_.initial.push_back(v);
    is_const_.push_back(1);
    total_.push_back(std::isfinite(v) ? 1 : 0);
    consts_.emplace(bits, s);
    return s;
  }
  std::uint32_t input() {
    const auto s = static_cast<std::uint32_t>(p_.initial.size());
    p_.initial.push_back(0.0);
    is_const_.push_back(0);
    total_.push_back(1);
    return s;
  }
  bool is_const(std::uint32_t s, double v) const { return is_const_[s] && p_.initial[s] == v; }

  /// Emits (or reuses) one scalar instruction. `total`: result finite for finite inputs.
  std::uint32_t emit(Code code, std::uint32_t a, std::uint32_t b = 0, std::uint32_t c = 0) {
    // Identities that never change a value (x·0 only when x is total).
    switch (code) {
      case Code::Add:
        if (is_const(b, 0.0)) return a;
        if (is_const(a, 0.0)) return b;
        break;
      case Code::Sub:
        if (is_const(b, 0.0)) return a;
        break;
      case Code::Mul:
        if (is_const(b, 1.0)) return a;
        if (is_const(a, 1.0)) return b;
        if (is_const(a, 0.0) && total_[b]) return a;
        if (is_const(b, 0.0) && total_[a]) return b;
        break;
      case Code::Div:
        if (is_const(b, 1.0)) return a;
        break;
      default:
        break;
    }
    const bool unary = code == Code::Neg || code == Code::Sqrt || code == Code::Exp || code == Code::Log ||
                       code == Code::Sin || code == Code::Cos || code == Code::Tan || code == Code::Asin ||
                       code == Code::Acos || code == Code::Atan || code == Code::Sinh || code == Code::Cosh ||
                       code == Code::Tanh || code == Code::Abs || code == Code::Sign || code == Code::PowI;
    const bool ca = is_const_[a];
    const bool cb = !unary && code != Code::Curve && is_const_[b];
    if (code != Code::Select && code != Code::Curve && ca && (unary || cb)) {
      return constant(fold(code, p_.initial[a], unary ? 0.0 : p_.initial[b], b));
    }
    if (code == Code::Select && is_const_[a] && !std::isnan(p_.initial[a])) return p_.initial[a] != 0.0 ? b : c;
    const std::array<std::uint32_t, 4> key{static_cast<std::uint32_t>(code), a, b, c};
    if (auto it = cse_.find(key); it != cse_.end()) return it->second;
    const auto s = static_cast<std::uint32_t>(p_.initial.size());
    p_.initial.push_back(0.0);
    is_const_.push_back(0);
    bool total = total_[a] && (unary || code == Code::Curve || total_[b]);
    switch (code) {
      case Code::Div:
      case Code::Pow:
      case Code::Sqrt:
      case Code::Log:
      case Code::Tan:
      case Code::Asin:
      case Code::Acos:
      case Code::Atan2:
        total = false;
        break;
      case Code::PowI:
        total = total && static_cast<std::int32_t>(b) >= 0;
        break;
      case Code::Select:
        total = total_[a] && total_[b] && total_[c];
        break;
      default:
        break;
    }
    total_.push_back(total ? 1 : 0);
    p_.code.push_back(Instr{code, s, a, b, c});
    cse_.emplace(key, s);
    return s;
  }

  static double fold(Code code, double a, double b, std::uint32_t raw_b);

  /// Slots of every node reachable from the roots, in post-order.
  void compile_node(NodeId id, const std::vector<std::uint32_t>& param_slot);

  std::vector<std::array<std::uint32_t, 3>> slots;  // per node id (valid once compiled)

 private:
  Tape::Program& p_;
  const Graph& g_;
  std::unordered_map<std::uint64_t, std::uint32_t> consts_;
  std::unordered_map<std::array<std::uint32_t, 4>, std::uint32_t, KeyHash> cse_;
  std::vector<char> is_const_;
  std::vector<char> total_;
  std::unordered_map<std::uint32_t, std::uint32_t> curve_map_;

 public:
  std::uint32_t curve_index(std::uint32_t graph_index) {
    if (auto it = curve_map_.find(graph_index); it != curve_map_.end()) return it->second;
    const auto k = static_cast<std::uint32_t>(p_.curves.size());
    p_.curves.push_back(g_.curves[graph_index]);
    curve_map_.emplace(graph_index, k);
    return k;
  }
};

/// One scalar instruction: the interpreter's inner switch, shared with constant folding.
inline double scalar(Code code, double a, double b, std::uint32_t raw_b) {
  switch (code) {
    case Code::Neg:
      return -a;
    case Code::Add:
      return a + b;
    case Code::Sub:
      return a - b;
    case Code::Mul:
      return a * b;
    case Code::Div:
      return op_div(a, b);
    case Code::Pow:
      return op_pow(a, b);
    case Code::PowI:
      return op_powi(a, static_cast<std::int32_t>(raw_b));
    case Code::Sqrt:
      return op_sqrt(a);
    case Code::Exp:
      return std::exp(a);
    case Code::Log:
      return op_log(a);
    case Code::Sin:
      return std::sin(a);
    case Code::Cos:
      return std::cos(a);
    case Code::Tan:
      return std::tan(a);
    case Code::Asin:
      return op_asin(a);
    case Code::Acos:
      return op_acos(a);
    case Code::Atan:
      return std::atan(a);
    case Code::Atan2:
      return op_atan2(a, b);
    case Code::Sinh:
      return std::sinh(a);
    case Code::Cosh:
      return std::cosh(a);
    case Code::Tanh:
      return std::tanh(a);
    case Code::Abs:
      return std::fabs(a);
    case Code::Sign:
      return op_sign(a);
    case Code::Min:
      return op_min(a, b);
    case Code::Max:
      return op_max(a, b);
    case Code::Less:
      return op_less(a, b);
    case Code::LessEq:
      return op_less_equal(a, b);
    default:
      break;
  }
  return kUndefined;
}

double Compiler::fold(Code code, double a, double b, std::uint32_t raw_b) { return scalar(code, a, b, raw_b); }

Code code_of(Op op) {
  switch (op) {
    case Op::Sqrt:
      return Code::Sqrt;
    case Op::Exp:
      return Code::Exp;
    case Op::Log:
      return Code::Log;
    case Op::Sin:
      return Code::Sin;
    case Op::Cos:
      return Code::Cos;
    case Op::Tan:
      return Code::Tan;
    case Op::Asin:
      return Code::Asin;
    case Op::Acos:
      return Code::Acos;
    case Op::Atan:
      return Code::Atan;
    case Op::Atan2:
      return Code::Atan2;
    case Op::Sinh:
      return Code::Sinh;
    case Op::Cosh:
      return Code::Cosh;
    case Op::Tanh:
      return Code::Tanh;
    case Op::Abs:
      return Code::Abs;
    case Op::Sign:
      return Code::Sign;
    case Op::Min:
      return Code::Min;
    case Op::Max:
      return Code::Max;
    case Op::Less:
      return Code::Less;
    case Op::LessEqual:
      return Code::LessEq;
    default:
      break;
  }
  throw InternalError("law tape: no scalar code for op");
}

void Compiler::compile_node(NodeId id, const std::vector<std::uint32_t>& param_slot) {
  const Node& n = g_.nodes[id];
  auto& out = slots[id];
  auto A = [&](std::size_t i) -> const std::array<std::uint32_t, 3>& { return slots[n.args[i]]; };
  const std::size_t dim = n.dimension;
  switch (n.op) {
    case Op::Constant:
      out[0] = constant(n.value);
      return;
    case Op::Parameter:
      out[0] = param_slot[n.index];
      return;
    case Op::Neg:
      for (std::size_t k = 0; k < dim; ++k) out[k] = emit(Code::Neg, A(0)[k]);
      return;
    case Op::Add:
    case Op::Sub:
      for (std::size_t k = 0; k < dim; ++k) out[k] = emit(n.op == Op::Add ? Code::Add : Code::Sub, A(0)[k], A(1)[k]);
      return;
    case Op::Mul: {
      const bool sa = g_.nodes[n.args[0]].dimension == 1;
      const bool sb = g_.nodes[n.args[1]].dimension == 1;
      for (std::size_t k = 0; k < dim; ++k) out[k] = emit(Code::Mul, A(0)[sa ? 0 : k], A(1)[sb ? 0 : k]);
      return;
    }
    case Op::Div:
      for (std::size_t k = 0; k < dim; ++k) out[k] = emit(Code::Div, A(0)[k], A(1)[0]);
      return;
    case Op::Pow: {
      const Node& e = g_.nodes[n.args[1]];
      if (e.op == Op::Constant && e.value == std::floor(e.value) && std::fabs(e.value) <= 4.0) {
        const auto k = static_cast<std::int32_t>(e.value);
        out[0] = emit(Code::PowI, A(0)[0], static_cast<std::uint32_t>(k));
      } else {
        out[0] = emit(Code::Pow, A(0)[0], A(1)[0]);
      }
      return;
    }
    case Op::Piecewise:
      for (std::size_t k = 0; k < dim; ++k) out[k] = emit(Code::Select, A(0)[0], A(1)[k], A(2)[k]);
      return;
    case Op::Vec:
      for (std::size_t k = 0; k < dim; ++k) out[k] = A(k)[0];
      return;
    case Op::Term:
      out[0] = A(0)[n.index - 1];
      return;
    case Op::Dot: {
      const std::size_t m = g_.nodes[n.args[0]].dimension;
      std::uint32_t s = emit(Code::Mul, A(0)[0], A(1)[0]);
      for (std::size_t k = 1; k < m; ++k) s = emit(Code::Add, s, emit(Code::Mul, A(0)[k], A(1)[k]));
      out[0] = s;
      return;
    }
    case Op::Cross: {
      const auto& a = A(0);
      const auto& b = A(1);
      out[0] = emit(Code::Sub, emit(Code::Mul, a[1], b[2]), emit(Code::Mul, a[2], b[1]));
      out[1] = emit(Code::Sub, emit(Code::Mul, a[2], b[0]), emit(Code::Mul, a[0], b[2]));
      out[2] = emit(Code::Sub, emit(Code::Mul, a[0], b[1]), emit(Code::Mul, a[1], b[0]));
      return;
    }
    case Op::Norm:
    case Op::Normalize: {
      const std::size_t m = g_.nodes[n.args[0]].dimension;
      const auto& a = A(0);
      std::uint32_t len;
      if (m == 1) {
        len = emit(Code::Abs, a[0]);
      } else {
        std::uint32_t s = emit(Code::Mul, a[0], a[0]);
        for (std::size_t k = 1; k < m; ++k) s = emit(Code::Add, s, emit(Code::Mul, a[k], a[k]));
        len = emit(Code::Sqrt, s);
      }
      if (n.op == Op::Norm) {
        out[0] = len;
      } else {
        for (std::size_t k = 0; k < m; ++k) out[k] = emit(Code::Div, a[k], len);
      }
      return;
    }
    case Op::Curve: {
      if (n.order > kMaxCurveOrder)
        throw Error(Errc::InvalidArgument, "law tape: NURBS leaf derivative order " + std::to_string(n.order) +
                                               " exceeds the limit of " + std::to_string(kMaxCurveOrder));
      // Three consecutive output slots, never shared by value numbering.
      const auto s = static_cast<std::uint32_t>(p_.initial.size());
      for (int k = 0; k < 3; ++k) {
        p_.initial.push_back(0.0);
        is_const_.push_back(0);
        total_.push_back(0);
      }
      p_.code.push_back(Instr{Code::Curve, s, A(0)[0], curve_index(n.index), n.order});
      out = {s, s + 1, s + 2};
      return;
    }
    default:
      out[0] = n.arity == 1 ? emit(code_of(n.op), A(0)[0]) : emit(code_of(n.op), A(0)[0], A(1)[0]);
      return;
  }
}

/// Replaces each pair Sin(a), Cos(a) by one SinCos at the earlier position (both only need a).
void fuse_sincos(Tape::Program& p) {
  std::unordered_map<std::uint32_t, std::size_t> sin_at, cos_at;
  for (std::size_t i = 0; i < p.code.size(); ++i) {
    if (p.code[i].code == Code::Sin) sin_at.emplace(p.code[i].a, i);
    if (p.code[i].code == Code::Cos) cos_at.emplace(p.code[i].a, i);
  }
  std::vector<char> drop(p.code.size(), 0);
  for (const auto& [arg, si] : sin_at) {
    auto it = cos_at.find(arg);
    if (it == cos_at.end()) continue;
    const std::size_t ci = it->second;
    const std::size_t first = std::min(si, ci);
    const Instr fused{Code::SinCos, p.code[si].out, arg, p.code[ci].out, 0};
    drop[si + ci - first] = 1;
    p.code[first] = fused;
  }
  std::vector<Instr> kept;
  kept.reserve(p.code.size());
  for (std::size_t i = 0; i < p.code.size(); ++i)
    if (!drop[i]) kept.push_back(p.code[i]);
  p.code = std::move(kept);
}

struct ThreadBuffer {
  std::uint64_t tape_id = 0;
  std::vector<double> slots;
};

}  // namespace

Tape Tape::compile(std::span<const Law> outputs, std::span<const std::string> inputs) {
  if (outputs.empty()) throw Error(Errc::InvalidArgument, "law tape: no outputs to compile");
  const auto& gp = Graph::of(outputs[0]);
  for (std::size_t i = 0; i < outputs.size(); ++i)
    if (!outputs[i].valid() || Graph::of(outputs[i]) != gp)
      throw Error(Errc::InvalidArgument,
                  "law tape: output " + std::to_string(i) + " is empty or belongs to another law context");
  const Graph& g = *gp;
  auto p = std::make_shared<Program>();
  p->id = g_next_tape_id.fetch_add(1);
  p->inputs = inputs.size();
  Compiler c(*p, g);
  constexpr std::uint32_t kUnbound = 0xffffffffU;
  std::vector<std::uint32_t> param_slot(g.parameter_names.size(), kUnbound);
  for (const auto& name : inputs) {
    const std::uint32_t s = c.input();
    for (std::size_t k = 0; k < g.parameter_names.size(); ++k)
      if (g.parameter_names[k] == name) param_slot[k] = s;
  }
  c.slots.assign(g.nodes.size(), {0, 0, 0});
  std::vector<char> state(g.nodes.size(), 0);  // 0 new, 1 on stack, 2 done
  std::vector<NodeId> stack;
  for (const Law& root : outputs) {
    stack.push_back(root.id());
    while (!stack.empty()) {
      const NodeId id = stack.back();
      if (state[id] == 2) {
        stack.pop_back();
        continue;
      }
      const Node& n = g.nodes[id];
      if (state[id] == 0) {
        state[id] = 1;
        for (std::size_t i = 0; i < n.arity; ++i)
          if (state[n.args[i]] == 0) stack.push_back(n.args[i]);
        continue;
      }
      stack.pop_back();
      if (n.op == Op::Parameter && param_slot[n.index] == kUnbound)
        throw Error(Errc::InvalidArgument,
                    "law tape: the law uses parameter '" + g.parameter_names[n.index] + "' which is not an input");
      c.compile_node(id, param_slot);
      state[id] = 2;
    }
    for (int k = 0; k < root.dimension(); ++k) p->outputs.push_back(c.slots[root.id()][static_cast<std::size_t>(k)]);
  }
  fuse_sincos(*p);
  Tape t;
  t.program_ = std::move(p);
  return t;
}

std::size_t Tape::input_count() const noexcept { return program_->inputs; }
std::size_t Tape::output_count() const noexcept { return program_->outputs.size(); }
std::size_t Tape::instruction_count() const noexcept { return program_->code.size(); }
std::size_t Tape::slot_count() const noexcept { return program_->initial.size(); }

Workspace Tape::make_workspace() const {
  Workspace w;
  w.tape_id_ = program_->id;
  w.slots_ = program_->initial;
  w.block_.resize(program_->initial.size() * kBlock);
  for (std::size_t k = 0; k < program_->initial.size(); ++k)
    for (std::size_t j = 0; j < kBlock; ++j) w.block_[k * kBlock + j] = program_->initial[k];
  return w;
}

void Tape::check(const Workspace& w) const {
  if (w.tape_id_ != program_->id)
    throw Error(Errc::InvalidArgument, "law tape: the workspace was not made by this tape (use make_workspace())");
}

namespace {

/// Runs the program on slots whose inputs are set. Hot loop: no allocation.
inline void run(const Tape::Program& p, double* s) {
  for (const Instr& in : p.code) {
    switch (in.code) {
      case Code::Add:
        s[in.out] = s[in.a] + s[in.b];
        break;
      case Code::Sub:
        s[in.out] = s[in.a] - s[in.b];
        break;
      case Code::Mul:
        s[in.out] = s[in.a] * s[in.b];
        break;
      case Code::Neg:
        s[in.out] = -s[in.a];
        break;
      case Code::Select:
        s[in.out] = op_select(s[in.a], s[in.b], s[in.c]);
        break;
      case Code::Curve: {
        const auto& curve = p.curves[in.b];
        const double t = s[in.a];
        const auto dom = curve.domain();
        if (!(t >= dom.start && t <= dom.end)) {
          s[in.out] = s[in.out + 1] = s[in.out + 2] = kUndefined;
          break;
        }
        std::array<Vec3, kMaxCurveOrder + 1> buf;
        curve.derivatives(t, static_cast<int>(in.c), std::span<Vec3>(buf.data(), in.c + 1));
        const Vec3& v = buf[in.c];
        s[in.out] = v.x;
        s[in.out + 1] = v.y;
        s[in.out + 2] = v.z;
        break;
      }
      case Code::PowI:
        s[in.out] = op_powi(s[in.a], static_cast<std::int32_t>(in.b));
        break;
      case Code::SinCos:
        s[in.out] = std::sin(s[in.a]);
        s[in.b] = std::cos(s[in.a]);
        break;
      default:  // b is a slot for every remaining code
        s[in.out] = scalar(in.code, s[in.a], s[in.b], 0);
        break;
    }
  }
}

/// Evaluates the NURBS leaf instruction for one parameter into three values.
inline void curve_value(const Tape::Program& p, const Instr& in, double t, double& x, double& y, double& z) {
  const auto& curve = p.curves[in.b];
  const auto dom = curve.domain();
  if (!(t >= dom.start && t <= dom.end)) {
    x = y = z = kUndefined;
    return;
  }
  std::array<Vec3, kMaxCurveOrder + 1> buf;
  curve.derivatives(t, static_cast<int>(in.c), std::span<Vec3>(buf.data(), in.c + 1));
  x = buf[in.c].x;
  y = buf[in.c].y;
  z = buf[in.c].z;
}

/// Instruction-major evaluation of n ≤ kBlock points held slot-major in s.
void run_block(const Tape::Program& p, double* s, std::size_t n) {
  constexpr std::size_t B = Tape::kBlock;
  for (const Instr& in : p.code) {
    double* o = s + static_cast<std::size_t>(in.out) * B;
    const double* a = s + static_cast<std::size_t>(in.a) * B;
    switch (in.code) {
      case Code::Add: {
        const double* b = s + static_cast<std::size_t>(in.b) * B;
        for (std::size_t j = 0; j < n; ++j) o[j] = a[j] + b[j];
        break;
      }
      case Code::Sub: {
        const double* b = s + static_cast<std::size_t>(in.b) * B;
        for (std::size_t j = 0; j < n; ++j) o[j] = a[j] - b[j];
        break;
      }
      case Code::Mul: {
        const double* b = s + static_cast<std::size_t>(in.b) * B;
        for (std::size_t j = 0; j < n; ++j) o[j] = a[j] * b[j];
        break;
      }
      case Code::Div: {
        const double* b = s + static_cast<std::size_t>(in.b) * B;
        for (std::size_t j = 0; j < n; ++j) o[j] = op_div(a[j], b[j]);
        break;
      }
      case Code::Neg:
        for (std::size_t j = 0; j < n; ++j) o[j] = -a[j];
        break;
      case Code::Sqrt:
        for (std::size_t j = 0; j < n; ++j) o[j] = op_sqrt(a[j]);
        break;
      case Code::PowI: {
        const auto k = static_cast<std::int32_t>(in.b);
        if (k == 2) {
          for (std::size_t j = 0; j < n; ++j) o[j] = a[j] * a[j];
        } else if (k == 3) {
          for (std::size_t j = 0; j < n; ++j) o[j] = a[j] * a[j] * a[j];
        } else {
          for (std::size_t j = 0; j < n; ++j) o[j] = op_powi(a[j], k);
        }
        break;
      }
      case Code::SinCos: {
        double* oc = s + static_cast<std::size_t>(in.b) * B;
        for (std::size_t j = 0; j < n; ++j) {
          o[j] = std::sin(a[j]);
          oc[j] = std::cos(a[j]);
        }
        break;
      }
      case Code::Select: {
        const double* b = s + static_cast<std::size_t>(in.b) * B;
        const double* c = s + static_cast<std::size_t>(in.c) * B;
        for (std::size_t j = 0; j < n; ++j) o[j] = op_select(a[j], b[j], c[j]);
        break;
      }
      case Code::Curve:
        for (std::size_t j = 0; j < n; ++j) curve_value(p, in, a[j], o[j], o[j + B], o[j + 2 * B]);
        break;
      default: {
        const double* b = s + static_cast<std::size_t>(in.b) * B;
        for (std::size_t j = 0; j < n; ++j) o[j] = scalar(in.code, a[j], b[j], 0);
        break;
      }
    }
  }
}

bool finish(const Tape::Program& p, const double* s, double* out) {
  bool ok = true;
  for (std::size_t k = 0; k < p.outputs.size(); ++k) {
    out[k] = s[p.outputs[k]];
    ok = ok && !std::isnan(out[k]);
  }
  return ok;
}

void size_check(const char* what, std::size_t got, std::size_t want) {
  if (got != want)
    throw Error(Errc::InvalidArgument, std::string("law tape: ") + what + " has " + std::to_string(got) +
                                           " values, expected " + std::to_string(want));
}

}  // namespace

bool Tape::evaluate(std::span<const double> inputs, std::span<double> outputs, Workspace& workspace) const {
  check(workspace);
  const Program& p = *program_;
  size_check("inputs", inputs.size(), p.inputs);
  size_check("outputs", outputs.size(), p.outputs.size());
  double* s = workspace.slots_.data();
  for (std::size_t i = 0; i < p.inputs; ++i) s[i] = inputs[i];
  run(p, s);
  return finish(p, s, outputs.data());
}

bool Tape::evaluate(std::span<const double> inputs, std::span<double> outputs) const {
  thread_local ThreadBuffer buffer;
  const Program& p = *program_;
  if (buffer.tape_id != p.id) {
    buffer.slots.assign(p.initial.begin(), p.initial.end());
    buffer.tape_id = p.id;
  }
  size_check("inputs", inputs.size(), p.inputs);
  size_check("outputs", outputs.size(), p.outputs.size());
  double* s = buffer.slots.data();
  for (std::size_t i = 0; i < p.inputs; ++i) s[i] = inputs[i];
  run(p, s);
  return finish(p, s, outputs.data());
}

namespace {
std::size_t run_batch(const Tape::Program& p, std::span<const double> inputs, std::span<double> outputs, double* s,
                      std::span<std::uint8_t> defined) {
  constexpr std::size_t B = Tape::kBlock;
  const std::size_t ni = p.inputs;
  const std::size_t no = p.outputs.size();
  const std::size_t n = ni == 0 ? outputs.size() / (no == 0 ? 1 : no) : inputs.size() / ni;
  size_check("inputs", inputs.size(), n * ni);
  size_check("outputs", outputs.size(), n * no);
  if (!defined.empty()) size_check("defined", defined.size(), n);
  std::size_t undefined = 0;
  for (std::size_t i0 = 0; i0 < n; i0 += B) {
    const std::size_t m = std::min(B, n - i0);
    for (std::size_t k = 0; k < ni; ++k)
      for (std::size_t j = 0; j < m; ++j) s[k * B + j] = inputs[(i0 + j) * ni + k];
    run_block(p, s, m);
    for (std::size_t j = 0; j < m; ++j) {
      bool ok = true;
      double* out = outputs.data() + (i0 + j) * no;
      for (std::size_t k = 0; k < no; ++k) {
        out[k] = s[static_cast<std::size_t>(p.outputs[k]) * B + j];
        ok = ok && !std::isnan(out[k]);
      }
      if (!ok) ++undefined;
      if (!defined.empty()) defined[i0 + j] = ok ? 1 : 0;
    }
  }
  return undefined;
}
}  // namespace

std::size_t Tape::evaluate(std::span<const double> inputs, std::span<double> outputs, Workspace& workspace,
                           std::span<std::uint8_t> defined) const {
  check(workspace);
  return run_batch(*program_, inputs, outputs, workspace.block_.data(), defined);
}

std::size_t Tape::evaluate(std::span<const double> inputs, std::span<double> outputs,
                           std::span<std::uint8_t> defined) const {
  thread_local Workspace buffer;
  if (buffer.tape_id_ != program_->id) {
    const std::size_t slots = program_->initial.size();
    buffer.block_.resize(slots * kBlock);
    for (std::size_t k = 0; k < slots; ++k)
      for (std::size_t j = 0; j < kBlock; ++j) buffer.block_[k * kBlock + j] = program_->initial[k];
    buffer.tape_id_ = program_->id;
  }
  return run_batch(*program_, inputs, outputs, buffer.block_.data(), defined);
}

// ---------------------------------------------------------------- CurveEvaluator

namespace {
Tape compile_curve(const Law& law, const std::string& parameter, int order) {
  if (order < 0 || order > 16)
    throw Error(Errc::InvalidArgument, "CurveEvaluator: order must be in [0, 16], got " + std::to_string(order));
  if (!law.valid()) throw Error(Errc::InvalidArgument, "CurveEvaluator: empty law");
  const std::vector<Law> laws = derivatives(law, parameter, order);
  const std::string inputs[1] = {parameter};
  return Tape::compile(laws, inputs);
}
}  // namespace

CurveEvaluator::CurveEvaluator(const Law& law, const std::string& parameter, int order)
    : tape_(compile_curve(law, parameter, order)), order_(order), dimension_(law.dimension()) {}

bool CurveEvaluator::derivatives(double t, std::span<Vec3> out) const {
  size_check("out", out.size(), static_cast<std::size_t>(order_ + 1));
  std::array<double, 3 * 17> buf{};
  const std::size_t no = tape_.output_count();
  const bool ok = tape_.evaluate(std::span<const double>(&t, 1), std::span<double>(buf.data(), no));
  const auto d = static_cast<std::size_t>(dimension_);
  for (std::size_t k = 0; k <= static_cast<std::size_t>(order_); ++k) {
    Vec3 v{0.0, 0.0, 0.0};
    for (std::size_t j = 0; j < d; ++j) v[j] = buf[k * d + j];
    out[k] = v;
  }
  return ok;
}

std::size_t CurveEvaluator::derivatives(std::span<const double> ts, std::span<Vec3> out) const {
  const auto m = static_cast<std::size_t>(order_ + 1);
  size_check("out", out.size(), ts.size() * m);
  const auto d = static_cast<std::size_t>(dimension_);
  const std::size_t no = tape_.output_count();
  std::array<double, 3 * 17 * Tape::kBlock> buf;  // one block of outputs, on the stack
  std::size_t undefined = 0;
  for (std::size_t i0 = 0; i0 < ts.size(); i0 += Tape::kBlock) {
    const std::size_t n = std::min(Tape::kBlock, ts.size() - i0);
    undefined += tape_.evaluate(ts.subspan(i0, n), std::span<double>(buf.data(), n * no), {});
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < m; ++k) {
        Vec3 v{0.0, 0.0, 0.0};
        for (std::size_t c = 0; c < d; ++c) v[c] = buf[j * no + k * d + c];
        out[(i0 + j) * m + k] = v;
      }
  }
  return undefined;
}

std::vector<Vec3> CurveEvaluator::derivatives(double t) const {
  std::vector<Vec3> out(static_cast<std::size_t>(order_ + 1));
  derivatives(t, out);
  return out;
}

}  // namespace hula::law
