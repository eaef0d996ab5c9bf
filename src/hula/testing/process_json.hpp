// SPDX-License-Identifier: MIT
// The JSON a `hula` command run by run_process printed: its stdout document, or
// the "error" object of the error JSON on stderr (docs/errors.md). One helper
// for every CLI test; a malformed stream is a test failure naming what it held.
#pragma once

#include <nlohmann/json.hpp>

#include "hula/testing/run_process.hpp"

namespace hula::testing {

/// stdout parsed as JSON, expecting exit code 0; a gtest failure (showing stdout and stderr) and an empty
/// object when the process failed or stdout is not JSON.
[[nodiscard]] nlohmann::json stdout_json(const ProcessResult& result);

/// The "error" member of the error JSON on stderr; a gtest failure (showing stderr) and an empty object
/// when stderr is not JSON.
[[nodiscard]] nlohmann::json stderr_error(const ProcessResult& result);

}  // namespace hula::testing
