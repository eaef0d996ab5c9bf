// SPDX-License-Identifier: MIT
// Shared helpers of the `hula` commands (see common.hpp).
#include "commands/common.hpp"

#include <charconv>
#include <cmath>
#include <iostream>
#include <limits>

#include "hula/core/error.hpp"
#include "hula/core/tolerance.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/json_write.hpp"

namespace hula::cli {

void print_json(const Json& document) { io::write_stdout(io::format_json(document)); }

void print_result(const Json& document, std::string_view output) {
  if (!io::is_std_stream(std::filesystem::path(output))) print_json(document);
}

void print_text(std::string_view text) { io::write_stdout(text); }

CLI::Option* add_format_option(CLI::App* sub, std::string& format, const std::string& records) {
  return sub
      ->add_option("--format", format,
                   "json (default: the JSON document) | jsonl (" + records +
                       ") | csv (a \"# name ...\" header, then one row per record) | text (one line per record)")
      ->check(CLI::IsMember({"json", "jsonl", "csv", "text"}));
}

void print_formatted(const Json& document, std::string_view format,
                     const std::function<io::Table(const Json&)>& make_table) {
  const std::optional<io::TableFormat> table = io::table_format_from_name(format);
  if (!table) {
    print_json(document);
    return;
  }
  print_text(io::format_table(make_table(document), *table));
}

namespace {
// At most a few characters of what the user typed, for messages.
std::string shown(std::string_view text) {
  constexpr std::size_t kMax = 24;
  return text.size() <= kMax ? std::string(text) : std::string(text.substr(0, kMax)) + "...";
}

std::string range_text(long long lo, long long hi) {
  if (hi == std::numeric_limits<long long>::max()) return ">= " + std::to_string(lo);
  return "in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
}
}  // namespace

long long parse_integer_option(std::string_view text, std::string_view flag, long long lo, long long hi, bool even) {
  const std::string rule = std::string("must be ") + (even ? "an even number " : "an integer ") + range_text(lo, hi);
  std::string_view s = text;
  if (s.size() > 1 && s.front() == '+') s.remove_prefix(1);
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  const std::string head = std::string(flag) + " " + shown(text);
  if (ec == std::errc::result_out_of_range)
    throw CLI::ValidationError(head, "outside the signed 64-bit range; " + rule);
  if (s.empty() || ec != std::errc() || ptr != s.data() + s.size())
    throw CLI::ValidationError(head, "not an integer; " + rule);
  if (v < lo || v > hi || (even && v % 2 != 0)) throw CLI::ValidationError(head, rule);
  return v;
}

double parse_real_option(std::string_view text, std::string_view flag, double lo, double hi, bool lo_open) {
  const auto fmt = [](double x) { return format_number(x); };
  std::string rule;
  if (hi == std::numeric_limits<double>::max())
    rule = std::string("must be a number ") + (lo_open ? "> " : ">= ") + fmt(lo);
  else
    rule = std::string("must be a number in ") + (lo_open ? "(" : "[") + fmt(lo) + ", " + fmt(hi) + "]";
  std::string_view s = text;
  if (s.size() > 1 && s.front() == '+') s.remove_prefix(1);
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  const std::string head = std::string(flag) + " " + shown(text);
  if (ec == std::errc::result_out_of_range) throw CLI::ValidationError(head, "outside the range of a double; " + rule);
  if (s.empty() || ec != std::errc() || ptr != s.data() + s.size())
    throw CLI::ValidationError(head, "not a number; " + rule);
  if (!std::isfinite(v) || v < lo || v > hi || (lo_open && v == lo)) throw CLI::ValidationError(head, rule);
  return v;
}

CLI::Option* add_real_option(CLI::App* sub, const std::string& flags, std::optional<double>& target, double lo,
                             double hi, bool lo_open, const std::string& help) {
  const std::string flag = "--" + flags.substr(flags.rfind("--") + 2);
  return sub
      ->add_option_function<std::string>(
          flags,
          [&target, flag, lo, hi, lo_open](const std::string& text) {
            target = parse_real_option(text, flag, lo, hi, lo_open);
          },
          help)
      ->type_name("NUMBER");
}

void add_exact_output_options(CLI::App* sub, std::string& output, std::optional<double>& to_nurbs, double& tolerance) {
  CLI::Option* out =
      sub->add_option("-o,--output", output,
                      "Write the curve file: the exact curve by its laws (kind natural), or its NURBS with --to-nurbs");
  add_real_option(sub, "--to-nurbs", to_nurbs, 0.0, 1.0, true,
                  "With -o: write the NURBS within this distance of the curve (model units) instead of the laws")
      ->needs(out);
  sub->add_option("--tolerance", tolerance,
                  "Position tolerance of the integration of the exact curve, in [1e-13, 1e-2] (default 1e-10)");
}

}  // namespace hula::cli
