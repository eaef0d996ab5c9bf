// SPDX-License-Identifier: MIT
// Recursive-descent parser of the law grammar (docs/formats.md):
//
//   expression := additive [ ("<" | "<=" | ">" | ">=") additive ]
//   additive   := multiplicative { ("+" | "-") multiplicative }
//   multiplicative := unary { ("*" | "/") unary }
//   unary      := ("-" | "+") unary | power
//   power      := primary [ "^" unary ]
//   primary    := number | "pi" | "e" | parameter | call | "(" expression ")"
//   call       := name "(" expression { "," expression } ")"
//
// Recursion is bounded by ParseOptions::max_depth, counted at every nesting
// step: an opening parenthesis, a call, a unary sign and a '^' exponent, the input by max_length and the output by
// max_nodes, so hostile input gets a positioned error instead of a stack overflow.
#include "hula/law/parser.hpp"

#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

#include "hula/core/error.hpp"
#include "hula/law/detail/graph.hpp"
#include "hula/law/detail/names.hpp"

namespace hula::law {

void ParseOptions::validate() const {
  auto bad = [](const std::string& field, const std::string& why) {
    throw Error(Errc::InvalidOption, "ParseOptions::" + field + " " + why, ErrorWhere{.field = field});
  };
  if (max_length < 1 || max_length > (std::size_t{16} << 20))
    bad("max_length", "must be in [1, 16777216], got " + std::to_string(max_length));
  if (max_depth < 1 || max_depth > 1000) bad("max_depth", "must be in [1, 1000], got " + std::to_string(max_depth));
  if (max_nodes < 1) bad("max_nodes", "must be >= 1, got 0");
  for (const auto& p : parameters)
    if (detail::is_reserved_name(p)) bad("parameters", "contains the reserved name '" + p + "'");
}

namespace {

struct Pos {
  std::size_t offset = 0;
  std::size_t line = 1;
  std::size_t column = 1;
};

enum class Tok {
  End,
  Number,
  Ident,
  Plus,
  Minus,
  Star,
  Slash,
  Caret,
  LParen,
  RParen,
  Comma,
  Less,
  LessEq,
  Greater,
  GreaterEq
};

const char* tok_name(Tok t) {
  switch (t) {
    case Tok::End:
      return "end of input";
    case Tok::Number:
      return "a number";
    case Tok::Ident:
      return "a name";
    case Tok::Plus:
      return "'+'";
    case Tok::Minus:
      return "'-'";
    case Tok::Star:
      return "'*'";
    case Tok::Slash:
      return "'/'";
    case Tok::Caret:
      return "'^'";
    case Tok::LParen:
      return "'('";
    case Tok::RParen:
      return "')'";
    case Tok::Comma:
      return "','";
    case Tok::Less:
      return "'<'";
    case Tok::LessEq:
      return "'<='";
    case Tok::Greater:
      return "'>'";
    case Tok::GreaterEq:
      return "'>='";
  }
  return "?";
}

bool is_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_hex(char c) { return is_digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

class Parser {
 public:
  Parser(std::string_view text, const Context& ctx, const ParseOptions& options)
      : text_(text), ctx_(ctx), options_(options), start_nodes_(ctx.node_count()) {}

  Law run() {
    if (text_.size() > options_.max_length)
      fail(Pos{}, "expression of " + std::to_string(text_.size()) + " bytes exceeds the limit of " +
                      std::to_string(options_.max_length) + " bytes (ParseOptions::max_length)");
    next();
    if (tok_ == Tok::End) fail(tok_pos_, "expected an expression, found end of input (empty expression)");
    Law e = expression();
    if (tok_ != Tok::End) fail(tok_pos_, "expected an operator or end of input, found " + describe());
    return e;
  }

 private:
  [[noreturn]] void fail(const Pos& p, const std::string& what) const {
    throw Error(Errc::ParseError,
                "line " + std::to_string(p.line) + ", column " + std::to_string(p.column) + ": " + what,
                ErrorWhere{.field = "expression", .line = p.line, .column = p.column});
  }

  std::string describe() const {
    if (tok_ == Tok::Number || tok_ == Tok::Ident)
      return std::string(tok_name(tok_)) + " '" + std::string(lexeme_) + "'";
    return tok_name(tok_);
  }

  // ------------------------------------------------------------ lexer
  char peek(std::size_t k = 0) const { return cur_.offset + k < text_.size() ? text_[cur_.offset + k] : '\0'; }
  void advance() {
    if (text_[cur_.offset] == '\n') {
      ++cur_.line;
      cur_.column = 1;
    } else {
      ++cur_.column;
    }
    ++cur_.offset;
  }

  void next() {
    while (cur_.offset < text_.size() &&
           (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r' || peek() == '\f' || peek() == '\v'))
      advance();
    tok_pos_ = cur_;
    const std::size_t begin = cur_.offset;
    if (cur_.offset >= text_.size()) {
      tok_ = Tok::End;
      lexeme_ = {};
      return;
    }
    const char c = peek();
    if (is_digit(c) || (c == '.' && is_digit(peek(1)))) {
      lex_number();
    } else if (is_alpha(c)) {
      while (cur_.offset < text_.size() && (is_alpha(peek()) || is_digit(peek()))) advance();
      tok_ = Tok::Ident;
    } else {
      advance();
      switch (c) {
        case '+':
          tok_ = Tok::Plus;
          break;
        case '-':
          tok_ = Tok::Minus;
          break;
        case '*':
          tok_ = Tok::Star;
          break;
        case '/':
          tok_ = Tok::Slash;
          break;
        case '^':
          tok_ = Tok::Caret;
          break;
        case '(':
          tok_ = Tok::LParen;
          break;
        case ')':
          tok_ = Tok::RParen;
          break;
        case ',':
          tok_ = Tok::Comma;
          break;
        case '<':
          tok_ = Tok::Less;
          if (peek() == '=') advance(), tok_ = Tok::LessEq;
          break;
        case '>':
          tok_ = Tok::Greater;
          if (peek() == '=') advance(), tok_ = Tok::GreaterEq;
          break;
        default: {
          const auto u = static_cast<unsigned char>(c);
          if (u >= 0x20 && u < 0x7f) fail(tok_pos_, std::string("unexpected character '") + c + "'");
          char buf[8];
          std::snprintf(buf, sizeof buf, "0x%02X", u);
          fail(tok_pos_, std::string("unexpected byte ") + buf + " (expressions are ASCII)");
        }
      }
    }
    lexeme_ = text_.substr(begin, cur_.offset - begin);
  }

  // Numbers in C notation: decimal and hexadecimal floating constants, and
  // decimal, octal (leading 0) and hexadecimal integer constants, with the C
  // suffixes (u, l, ll for integers; f rounds to float, l keeps double).
  void lex_number() {
    const Pos start = cur_;
    const std::size_t begin = cur_.offset;
    bool hex = false;
    bool is_float = false;
    if (peek() == '0' && (peek(1) == 'x' || peek(1) == 'X')) {
      hex = true;
      advance();
      advance();
      while (is_hex(peek())) advance();
      if (peek() == '.') {
        is_float = true;
        advance();
        while (is_hex(peek())) advance();
      }
      if (peek() == 'p' || peek() == 'P') {
        is_float = true;
        advance();
        if (peek() == '+' || peek() == '-') advance();
        if (!is_digit(peek())) bad_number(start, begin, "missing binary exponent digits");
        while (is_digit(peek())) advance();
      }
    } else {
      while (is_digit(peek())) advance();
      if (peek() == '.') {
        is_float = true;
        advance();
        while (is_digit(peek())) advance();
      }
      if (peek() == 'e' || peek() == 'E') {
        // "2e" followed by something that is not an exponent would read as 2·e in
        // algebra, but in C it is a malformed constant: say so.
        is_float = true;
        advance();
        if (peek() == '+' || peek() == '-') advance();
        if (!is_digit(peek())) bad_number(start, begin, "missing exponent digits");
        while (is_digit(peek())) advance();
      }
    }
    const std::size_t digits_end = cur_.offset;
    bool as_float = false;
    if (is_float) {
      if (peek() == 'f' || peek() == 'F') {
        as_float = true;
        advance();
      } else if (peek() == 'l' || peek() == 'L') {
        advance();
      }
    } else {
      while (peek() == 'u' || peek() == 'U' || peek() == 'l' || peek() == 'L') advance();
    }
    if (is_alpha(peek()) || is_digit(peek()) || peek() == '.') {
      while (is_alpha(peek()) || is_digit(peek()) || peek() == '.') advance();
      bad_number(start, begin, "invalid characters in number");
    }
    const std::string_view digits = text_.substr(begin, digits_end - begin);
    double v = 0.0;
    if (hex) {
      const std::string_view body = digits.substr(2);
      if (body.empty() || body == ".") bad_number(start, begin, "no hexadecimal digits");
      auto r = std::from_chars(body.data(), body.data() + body.size(), v, std::chars_format::hex);
      if (r.ec == std::errc::result_out_of_range) bad_number(start, begin, "out of the range of double");
      if (r.ec != std::errc() || r.ptr != body.data() + body.size()) bad_number(start, begin, "malformed");
    } else if (!is_float && digits.size() > 1 && digits[0] == '0') {
      for (char ch : digits) {
        if (ch == '8' || ch == '9')
          bad_number(start, begin, std::string("invalid digit '") + ch + "' in octal constant");
        v = v * 8.0 + (ch - '0');
      }
    } else {
      auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
      if (r.ec == std::errc::result_out_of_range) bad_number(start, begin, "out of the range of double");
      if (r.ec != std::errc() || r.ptr != digits.data() + digits.size()) bad_number(start, begin, "malformed");
    }
    if (as_float) v = static_cast<double>(static_cast<float>(v));
    if (!std::isfinite(v)) bad_number(start, begin, "out of the range of double");
    value_ = v;
    tok_ = Tok::Number;
  }

  [[noreturn]] void bad_number(const Pos& p, std::size_t begin, const std::string& why) {
    std::size_t end = cur_.offset;
    if (end - begin > 40) end = begin + 40;
    fail(p, "malformed number '" + std::string(text_.substr(begin, end - begin)) + "': " + why);
  }

  // ------------------------------------------------------------ grammar
  struct DepthGuard {
    Parser& p;
    DepthGuard(Parser& parser, const Pos& at) : p(parser) {
      if (++p.depth_ > p.options_.max_depth)
        p.fail(at, "expression nested deeper than the limit of " + std::to_string(p.options_.max_depth) +
                       " levels (ParseOptions::max_depth)");
    }
    ~DepthGuard() { --p.depth_; }
    DepthGuard(const DepthGuard&) = delete;
    DepthGuard& operator=(const DepthGuard&) = delete;
  };

  /// Runs a builder; its dimension errors and DAG limits become positioned parse errors.
  template <class F>
  Law build(const Pos& at, F&& f) {
    Law out;
    try {
      out = f();
    } catch (const Error& e) {
      if (e.code() == Errc::ParseError) throw;  // already positioned (e.g. a bad term index)
      fail(at, e.message());
    }
    if (ctx_.node_count() - start_nodes_ > options_.max_nodes)
      fail(at,
           "expression creates more than " + std::to_string(options_.max_nodes) + " nodes (ParseOptions::max_nodes)");
    return out;
  }

  void expect(Tok t, const std::string& context) {
    if (tok_ != t) fail(tok_pos_, std::string("expected ") + tok_name(t) + " " + context + ", found " + describe());
    next();
  }

  Law expression() {
    Law a = additive();
    if (tok_ == Tok::Less || tok_ == Tok::LessEq || tok_ == Tok::Greater || tok_ == Tok::GreaterEq) {
      const Tok op = tok_;
      const Pos at = tok_pos_;
      next();
      Law b = additive();
      if (tok_ == Tok::Less || tok_ == Tok::LessEq || tok_ == Tok::Greater || tok_ == Tok::GreaterEq)
        fail(tok_pos_, "comparison operators do not chain: found " + describe() + " after a comparison");
      return build(at, [&] {
        switch (op) {
          case Tok::Less:
            return less(a, b);
          case Tok::LessEq:
            return less_equal(a, b);
          case Tok::Greater:
            return less(b, a);
          default:
            return less_equal(b, a);
        }
      });
    }
    return a;
  }

  Law additive() {
    Law a = multiplicative();
    while (tok_ == Tok::Plus || tok_ == Tok::Minus) {
      const Tok op = tok_;
      const Pos at = tok_pos_;
      next();
      Law b = multiplicative();
      a = build(at, [&] { return op == Tok::Plus ? a + b : a - b; });
    }
    return a;
  }

  Law multiplicative() {
    Law a = unary();
    while (tok_ == Tok::Star || tok_ == Tok::Slash) {
      const Tok op = tok_;
      const Pos at = tok_pos_;
      next();
      Law b = unary();
      a = build(at, [&] { return op == Tok::Star ? a * b : a / b; });
    }
    return a;
  }

  Law unary() {
    if (tok_ == Tok::Minus || tok_ == Tok::Plus) {
      const Tok op = tok_;
      const Pos at = tok_pos_;
      DepthGuard guard(*this, at);  // "- - - t" nests
      next();
      Law a = unary();
      if (op == Tok::Plus) return a;
      return build(at, [&] { return -a; });
    }
    return power();
  }

  Law power() {
    Law base = primary();
    if (tok_ == Tok::Caret) {
      const Pos at = tok_pos_;
      DepthGuard guard(*this, at);  // "t^t^t" nests to the right
      next();
      Law exponent = unary();
      return build(at, [&] { return pow(base, exponent); });
    }
    return base;
  }

  Law primary() {
    const Pos at = tok_pos_;
    switch (tok_) {
      case Tok::Number: {
        const double v = value_;
        next();
        return build(at, [&] { return ctx_.constant(v); });
      }
      case Tok::LParen: {
        DepthGuard guard(*this, at);
        next();
        Law e = expression();
        if (tok_ != Tok::RParen)
          fail(tok_pos_, "expected ')' to close the '(' at line " + std::to_string(at.line) + ", column " +
                             std::to_string(at.column) + ", found " + describe());
        next();
        return e;
      }
      case Tok::Ident:
        return identifier();
      default:
        fail(at, "expected a number, a name or '(', found " + describe());
    }
  }

  Law identifier() {
    const Pos at = tok_pos_;
    const std::string name(lexeme_);
    next();
    if (tok_ == Tok::LParen) return call(name, at);
    if (name == "pi") return build(at, [&] { return ctx_.constant(std::numbers::pi); });
    if (name == "e") return build(at, [&] { return ctx_.constant(std::numbers::e); });
    for (const auto& p : options_.parameters)
      if (p == name) return build(at, [&] { return ctx_.parameter(name); });
    if (detail::find_function(name) != nullptr || ctx_.find_curve(name) >= 0)
      fail(tok_pos_, "expected '(' after the function '" + name + "', found " + describe());
    std::string known;
    for (const auto& p : options_.parameters) known += (known.empty() ? "" : ", ") + p;
    fail(at, "unknown identifier '" + name + "' (parameters: " + (known.empty() ? "none" : known) + ")");
  }

  Law call(const std::string& name, const Pos& at) {
    DepthGuard guard(*this, at);
    const detail::FunctionInfo* f = detail::find_function(name);
    const int curve = f == nullptr ? ctx_.find_curve(name) : -1;
    if (f == nullptr && curve < 0) {
      bool is_param = false;
      for (const auto& p : options_.parameters) is_param = is_param || p == name;
      fail(at, is_param ? "'" + name + "' is a parameter, not a function" : "unknown function '" + name + "'");
    }
    next();  // '('
    std::vector<Law> args;
    std::vector<Pos> arg_pos;
    if (tok_ != Tok::RParen) {
      for (;;) {
        arg_pos.push_back(tok_pos_);
        args.push_back(expression());
        if (tok_ != Tok::Comma) break;
        next();
      }
    }
    if (tok_ != Tok::RParen)
      fail(tok_pos_, "expected ',' or ')' in the arguments of '" + name + "', found " + describe());
    next();
    const int n = static_cast<int>(args.size());
    const int min_args = f != nullptr ? f->min_args : 1;
    const int max_args = f != nullptr ? f->max_args : 2;
    if (n < min_args || n > max_args) {
      const std::string want = min_args == max_args ? std::to_string(min_args)
                                                    : std::to_string(min_args) + " or " + std::to_string(max_args);
      fail(at,
           "'" + name + "' takes " + want + " argument" + (max_args == 1 ? "" : "s") + ", got " + std::to_string(n));
    }
    auto integer_arg = [&](std::size_t i, const char* what, int lo) {
      const Law& a = args[i];
      if (!a.is_constant() || a.node().value != std::floor(a.node().value) || a.node().value < lo ||
          a.node().value > 1e6)
        fail(arg_pos[i], "'" + name + "': " + what + " must be an integer constant >= " + std::to_string(lo));
      return static_cast<int>(a.node().value);
    };
    if (curve >= 0) {
      const int order = n == 2 ? integer_arg(1, "the derivative order", 0) : 0;
      return build(at,
                   [&] { return ctx_.curve(ctx_.curve_at(static_cast<std::uint32_t>(curve)), args[0], name, order); });
    }
    return build(at, [&]() -> Law {
      if (f->op == Op::Term) {
        const Law vector[1] = {args[0]};
        return detail::build(Op::Term, vector, integer_arg(1, "the component index", 1));
      }
      return detail::build(f->op, args);
    });
  }

  std::string_view text_;
  Context ctx_;
  const ParseOptions& options_;
  std::size_t start_nodes_;
  std::size_t depth_ = 0;
  Pos cur_{};
  Pos tok_pos_{};
  Tok tok_ = Tok::End;
  std::string_view lexeme_{};
  double value_ = 0.0;
};

}  // namespace

Law parse(std::string_view text, const Context& context, const ParseOptions& options) {
  options.validate();
  return Parser(text, context, options).run();
}

}  // namespace hula::law
