// SPDX-License-Identifier: MIT
#include "hula/testing/process_json.hpp"

#include <gtest/gtest.h>

#include <exception>

namespace hula::testing {

nlohmann::json stdout_json(const ProcessResult& result) {
  EXPECT_EQ(result.exit_code, 0) << result.err;
  try {
    return nlohmann::json::parse(result.out);
  } catch (const std::exception&) {
    ADD_FAILURE() << "stdout is not JSON: " << result.out << result.err;
    return nlohmann::json::object();
  }
}

nlohmann::json stderr_error(const ProcessResult& result) {
  try {
    return nlohmann::json::parse(result.err).at("error");
  } catch (const std::exception&) {
    ADD_FAILURE() << "stderr is not the error JSON: " << result.err;
    return nlohmann::json::object();
  }
}

}  // namespace hula::testing
