// SPDX-License-Identifier: MIT
// IGES counts against the parameters that follow them (iges_counts.hpp). The
// parameter data section (column 73 'P') holds, in columns 1–64, each entity's
// parameters separated by the global section's parameter delimiter (',' by
// default) and ended by its record delimiter (';'); columns 65–72 give the
// entity's directory entry, which groups the lines of one entity.
#include "hula/io/iges_counts.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "hula/core/error.hpp"

namespace hula::io {

namespace {

// One entity's parameters as they are read: the first few kept, every one counted.
class Entity {
 public:
  void start(std::string de) {
    de_ = std::move(de);
    token_.clear();
    first_.clear();
    count_ = 0;
    ended_ = false;
  }
  [[nodiscard]] bool started() const { return !de_.empty(); }
  [[nodiscard]] const std::string& de() const { return de_; }

  void feed(std::string_view data, char delimiter, char end) {
    for (std::size_t i = 0; i < data.size() && !ended_; ++i) {
      const char c = data[i];
      if (c == delimiter || c == end) {
        take();
        if (c == end) ended_ = true;
      } else if (c == 'H' && !token_.empty() && is_count(token_)) {
        // A Hollerith string nH...: its n characters are one parameter, delimiters included.
        const std::size_t n = std::strtoul(token_.c_str(), nullptr, 10);
        const std::size_t skip = std::min(n, data.size() - i - 1);
        i += skip;
        token_ = "H";
      } else if (c != ' ' && token_.size() < 32) {
        token_ += c;
      }
    }
  }

  // Refuses a count above what the entity holds.
  void check(std::string_view name) {
    if (!started()) return;
    if (!ended_) take();
    if (first_.empty()) return;
    const long long type = number(0);
    const long long held = static_cast<long long>(count_);
    const auto refuse = [&](const char* what, long long value, long long needs) {
      throw Error(Errc::ParseError,
                  "cannot read IGES '" + std::string(name) + "': the entity of directory entry " + de_ + " (type " +
                      std::to_string(type) + ") states " + what + " = " + std::to_string(value) +
                      (needs < 0 ? ", more than the " + std::to_string(held) + " parameters it holds"
                                 : ", which needs " + std::to_string(needs) + " parameters, but it holds " +
                                       std::to_string(held)),
                  ErrorWhere{.field = "path"});
    };
    // Each count alone must not exceed the parameters held; then the arrays it implies must fit.
    const auto bounded = [&](const char* what, std::size_t at) {
      const long long v = number(at);
      if (v > held) refuse(what, v, -1);
      return v < 0 ? 0 : v;
    };
    switch (type) {
      case 102:
        (void)bounded("N", 1);
        break;
      case 106: {
        const long long n = bounded("N", 2);
        if (2 * n > held) refuse("N", n, 2 * n);
        break;
      }
      case 112: {
        const long long n = bounded("N", 4);
        if (13 * n > held) refuse("N", n, 13 * n);
        break;
      }
      case 114: {
        const long long m = bounded("M", 3), n = bounded("N", 4);
        if (m + n + 2 > held || m * n > held) refuse("M × N", m * n, m + n + 2 + m * n);
        break;
      }
      case 126: {
        const long long k = bounded("K", 1), m = bounded("M", 2);
        if (k + m + 2 + 4 * (k + 1) > held) refuse("K", k, k + m + 2 + 4 * (k + 1));
        break;
      }
      case 128: {
        const long long k1 = bounded("K1", 1), k2 = bounded("K2", 2), m1 = bounded("M1", 3), m2 = bounded("M2", 4);
        const long long poles = (k1 + 1) * (k2 + 1);  // each ≤ held + 1, so no overflow for any real file
        if (k1 + m1 + 2 + k2 + m2 + 2 + 4 * poles > held)
          refuse("(K1 + 1) × (K2 + 1)", poles, k1 + m1 + 2 + k2 + m2 + 2 + 4 * poles);
        break;
      }
      default:
        break;
    }
  }

 private:
  static bool is_count(const std::string& t) { return t.find_first_not_of("0123456789") == std::string::npos; }
  void take() {
    if (first_.size() < 6) first_.push_back(token_);
    ++count_;
    token_.clear();
  }
  // The parameter `at` (0: the entity type) as an integer; 0 when absent or not an integer.
  [[nodiscard]] long long number(std::size_t at) const {
    if (at >= first_.size()) return 0;
    char* end = nullptr;
    const long long v = std::strtoll(first_[at].c_str(), &end, 10);
    return end == first_[at].c_str() ? 0 : v;
  }
  std::string de_;
  std::string token_;
  std::vector<std::string> first_;
  std::size_t count_ = 0;
  bool ended_ = false;
};

}  // namespace

void check_iges_counts(std::istream& in, std::string_view name) {
  char delimiter = ',', end = ';';
  std::string global;  // the start of the global section: its first two parameters name the delimiters
  Entity entity;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.size() < 73) continue;
    const char section = line[72];
    if (section == 'G' && global.size() < 16) {
      global += line.substr(0, 72);
      if (global.rfind("1H", 0) == 0 && global.size() > 2) delimiter = global[2];
      const std::size_t second = global.rfind("1H", 0) == 0 ? 4 : 1;  // after "1H," + delimiter, or after ","
      if (global.compare(second, 2, "1H") == 0 && global.size() > second + 2) end = global[second + 2];
      continue;
    }
    if (section != 'P') continue;
    std::string de = line.substr(64, 8);
    de.erase(0, std::min(de.find_first_not_of(" 0"), de.size() - 1));  // "      12" or "0000012": 12
    if (!entity.started() || de != entity.de()) {
      entity.check(name);
      entity.start(de);
    }
    entity.feed(std::string_view(line).substr(0, 64), delimiter, end);
  }
  entity.check(name);
}

void check_iges_file_counts(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return;  // the reader names a file it cannot open
  check_iges_counts(in, path.string());
}

}  // namespace hula::io
