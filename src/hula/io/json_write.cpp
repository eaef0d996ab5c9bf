// SPDX-License-Identifier: MIT
// format_json: a small recursive printer over nlohmann values (see json_write.hpp).
#include "hula/io/json_write.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <system_error>

namespace hula::io {
namespace {

using json::Json;

// The exponent of a number in scientific notation as nlohmann writes it: a sign and at least two
// digits ("e+07", "e-123").
void put_exponent(std::string& out, int e) {
  out += e < 0 ? '-' : '+';
  e = std::abs(e);
  if (e >= 100) out += static_cast<char>('0' + e / 100);
  out += static_cast<char>('0' + e / 10 % 10);
  out += static_cast<char>('0' + e % 10);
}

// A finite non-zero double: the shortest digits that read back as the same double (std::to_chars,
// no locale, no allocation), laid out as nlohmann::json's dump() lays out its own digits, so files
// keep their look: fixed notation with at least one decimal ("12.0", "0.0001") for decimal
// exponents in (-4, 15], scientific otherwise ("1e+16", "1.5e-05").
void put_double(std::string& out, double v) {
  if (std::signbit(v)) {
    out += '-';
    v = -v;
  }
  std::array<char, 32> sci{};  // d.ddddde±XXX: at most 17 digits, point, exponent
  const auto [end, ec] = std::to_chars(sci.data(), sci.data() + sci.size(), v, std::chars_format::scientific);
  (void)ec;  // cannot fail: 32 characters hold every double
  const char* e_at = static_cast<const char*>(std::memchr(sci.data(), 'e', static_cast<std::size_t>(end - sci.data())));
  int exp10 = 0;
  std::from_chars(e_at + (e_at[1] == '+' ? 2 : 1), end, exp10);
  std::array<char, 17> digits{};
  int k = 0;
  for (const char* c = sci.data(); c != e_at; ++c)
    if (*c != '.') digits[static_cast<std::size_t>(k++)] = *c;
  const int n = exp10 + 1;  // v = 0.d1d2…dk × 10^n
  const std::string_view d(digits.data(), static_cast<std::size_t>(k));
  constexpr int kMinExp = -4, kMaxExp = 15;  // nlohmann's bounds for fixed notation
  if (k <= n && n <= kMaxExp) {              // digits[000].0
    out += d;
    out.append(static_cast<std::size_t>(n - k), '0');
    out += ".0";
  } else if (0 < n && n <= kMaxExp) {  // dig.its
    out += d.substr(0, static_cast<std::size_t>(n));
    out += '.';
    out += d.substr(static_cast<std::size_t>(n));
  } else if (kMinExp < n && n <= 0) {  // 0.[000]digits
    out += "0.";
    out.append(static_cast<std::size_t>(-n), '0');
    out += d;
  } else {  // d[.igits]e±XX
    out += d[0];
    if (k > 1) {
      out += '.';
      out += d.substr(1);
    }
    out += 'e';
    put_exponent(out, n - 1);
  }
}

template <class Int>
void put_integer(std::string& out, Int v) {
  std::array<char, 24> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
  (void)ec;  // cannot fail: 24 characters hold every 64-bit integer
  out.append(buffer.data(), end);
}

bool is_scalar(const Json& v) { return !v.is_array() && !v.is_object(); }

void put_scalar(std::string& out, const Json& v) {
  switch (v.type()) {
    case Json::value_t::number_float:
      append_json_number(out, v.get_ref<const Json::number_float_t&>());
      return;
    case Json::value_t::number_integer:
      put_integer(out, v.get_ref<const Json::number_integer_t&>());
      return;
    case Json::value_t::number_unsigned:
      put_integer(out, v.get_ref<const Json::number_unsigned_t&>());
      return;
    default:
      out += v.dump(-1, ' ', false, Json::error_handler_t::replace);
  }
}

void put(std::string& out, const Json& v, std::size_t indent, bool compact) {
  if (is_scalar(v)) {
    put_scalar(out, v);
    return;
  }
  const bool array = v.is_array();
  if (v.empty()) {
    out += array ? "[]" : "{}";
    return;
  }
  bool inline_all = compact;
  if (array && !inline_all) {
    inline_all = true;
    for (const Json& e : v)
      if (!is_scalar(e)) {
        inline_all = false;
        break;
      }
  }
  out += array ? '[' : '{';
  bool first = true;
  for (auto it = v.begin(); it != v.end(); ++it) {
    if (!first) out += inline_all ? (compact ? "," : ", ") : ",";
    first = false;
    if (!inline_all) {
      out += '\n';
      out.append(indent + 2, ' ');
    }
    if (!array) {
      out += Json(it.key()).dump(-1, ' ', false, Json::error_handler_t::replace);
      out += compact ? ":" : ": ";
    }
    put(out, *it, indent + 2, compact);
  }
  if (!inline_all) {
    out += '\n';
    out.append(indent, ' ');
  }
  out += array ? ']' : '}';
}

}  // namespace

void append_json_number(std::string& out, double v) {
  if (v == 0.0)
    out += "0.0";  // -0.0 compares equal to 0.0: both print as 0.0
  else if (!std::isfinite(v))
    out += "null";  // as nlohmann writes NaN and infinities
  else
    put_double(out, v);
}

std::string format_json(const json::Json& value) {
  std::string out;
  put(out, value, 0, false);
  out += '\n';
  return out;
}

std::string format_json_line(const json::Json& value) {
  std::string out;
  put(out, value, 0, true);
  out += '\n';
  return out;
}

}  // namespace hula::io
