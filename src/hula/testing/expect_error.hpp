// SPDX-License-Identifier: MIT
// HULA_EXPECT_ERROR(statement, code, substring): the statement throws
// hula::Error with the given code and a message containing the substring
// (STYLE.md rule 8: every documented error checks its code and that the
// message names the offending index or value).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "hula/core/error.hpp"

#define HULA_EXPECT_ERROR(statement, expected_code, substring)                                          \
  do {                                                                                                  \
    bool hula_thrown_ = false;                                                                          \
    try {                                                                                               \
      (void)(statement);                                                                                \
    } catch (const ::hula::Error& hula_e_) {                                                            \
      hula_thrown_ = true;                                                                              \
      EXPECT_EQ(::hula::errc_name(hula_e_.code()), ::hula::errc_name(expected_code)) << hula_e_.what(); \
      EXPECT_NE(std::string(hula_e_.what()).find(substring), std::string::npos)                         \
          << "message \"" << hula_e_.what() << "\" does not contain \"" << (substring) << "\"";         \
    }                                                                                                   \
    EXPECT_TRUE(hula_thrown_) << #statement " did not throw hula::Error";                               \
  } while (false)
