// SPDX-License-Identifier: MIT
// The law text shortened for messages and reports (singularities, integrate): one place, so the
// sources of hula::law can share a unity translation unit (HULA_UNITY_BUILD).
#pragma once

#include <string>

#include "hula/law/expr.hpp"
#include "hula/law/parser.hpp"

namespace hula::law::detail {

/// print(l), cut to 117 characters and "..." when longer than 120.
inline std::string short_print(const Law& l) {
  std::string s = print(l);
  if (s.size() > 120) s = s.substr(0, 117) + "...";
  return s;
}

}  // namespace hula::law::detail
