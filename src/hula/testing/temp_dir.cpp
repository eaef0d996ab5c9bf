// SPDX-License-Identifier: MIT
#include "hula/testing/temp_dir.hpp"

#include <stdlib.h>

#include <algorithm>
#include <stdexcept>
#include <system_error>

namespace hula::testing {

TempDir::TempDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "hula-test-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed for " + pattern);
  path_ = pattern;
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::vector<std::string> TempDir::names() const {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(path_)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace hula::testing
