// SPDX-License-Identifier: MIT
// A fresh, empty temporary directory for file tests, removed with everything
// in it when the object goes out of scope.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace hula::testing {

/// A directory `<system temp>/hula-test-XXXXXX` created by mkdtemp.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const noexcept { return path_; }
  /// path() / name.
  [[nodiscard]] std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  /// Names of the entries directly inside, sorted.
  [[nodiscard]] std::vector<std::string> names() const;

 private:
  std::filesystem::path path_;
};

}  // namespace hula::testing
