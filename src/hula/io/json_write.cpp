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

// A finite non-zero double: the shortest digits that read back as the same double (std::to_chars,
// no locale, no allocation), laid out as nlohmann::json's dump() lays out its own digits, so files
// keep their look: fixed notation with at least one decimal ("12.0", "0.0001") for decimal
// exponents in (-4, 15], scientific otherwise ("1e+16", "1.5e-05", the exponent with a sign and at
// least two digits). The text is laid out in a local buffer and appended once.
void put_double(std::string& out, double v) {
  std::array<char, 48> text{};  // at most: sign, "0.0000", 17 digits; or 17 digits, '.', "e-324"
  char* o = text.data();
  if (std::signbit(v)) {
    *o++ = '-';
    v = -v;
  }
  std::array<char, 32> sci{};  // d.ddddde±XXX: at most 17 digits, point, exponent
  const auto [end, ec] = std::to_chars(sci.data(), sci.data() + sci.size(), v, std::chars_format::scientific);
  (void)ec;  // cannot fail: 32 characters hold every double
  // The digits without the point, then the exponent after 'e' (always signed by to_chars).
  std::array<char, 17> digits{};
  int k = 0;
  const char* c = sci.data();
  for (; *c != 'e'; ++c)
    if (*c != '.') digits[static_cast<std::size_t>(k++)] = *c;
  const bool negative_exp = c[1] == '-';
  int exp10 = 0;
  for (const char* e = c + 2; e != end; ++e) exp10 = 10 * exp10 + (*e - '0');
  if (negative_exp) exp10 = -exp10;
  const int n = exp10 + 1;  // v = 0.d1d2…dk × 10^n
  const auto put = [&o](const char* from, int count) {
    std::memcpy(o, from, static_cast<std::size_t>(count));
    o += count;
  };
  const auto zeros = [&o](int count) {
    std::memset(o, '0', static_cast<std::size_t>(count));
    o += count;
  };
  constexpr int kMinExp = -4, kMaxExp = 15;  // nlohmann's bounds for fixed notation
  if (k <= n && n <= kMaxExp) {              // digits[000].0
    put(digits.data(), k);
    zeros(n - k);
    put(".0", 2);
  } else if (0 < n && n <= kMaxExp) {  // dig.its
    put(digits.data(), n);
    *o++ = '.';
    put(digits.data() + n, k - n);
  } else if (kMinExp < n && n <= 0) {  // 0.[000]digits
    put("0.", 2);
    zeros(-n);
    put(digits.data(), k);
  } else {  // d[.igits]e±XX
    *o++ = digits[0];
    if (k > 1) {
      *o++ = '.';
      put(digits.data() + 1, k - 1);
    }
    *o++ = 'e';
    int e = n - 1;
    *o++ = e < 0 ? '-' : '+';
    e = std::abs(e);
    if (e >= 100) *o++ = static_cast<char>('0' + e / 100);
    *o++ = static_cast<char>('0' + e / 10 % 10);
    *o++ = static_cast<char>('0' + e % 10);
  }
  out.append(text.data(), o);
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
