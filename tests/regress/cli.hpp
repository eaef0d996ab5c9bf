// SPDX-License-Identifier: MIT
// Helpers of the issue-10 regression tests: run the built `hula`, read its
// error JSON, write input files, and list a directory's hidden temporaries.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hula/io/atomic_file.hpp"
#include "hula/testing/process_json.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif

namespace hula::regress {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::ProcessOptions;
using testing::ProcessResult;
using testing::TempDir;

inline ProcessResult hula(const std::vector<std::string>& args, const ProcessOptions& options = {}) {
  return testing::run_process(HULA_CLI_PATH, args, options);
}

/// The error JSON on stderr, {"error": {...}} (a failure is recorded when it is not the error JSON).
inline json error_of(const ProcessResult& r) { return json{{"error", testing::stderr_error(r)}}; }

/// The error message on stderr.
inline std::string message_of(const ProcessResult& r) {
  const json e = error_of(r);
  return e.contains("error") ? e["error"].value("message", std::string()) : std::string();
}

inline void write(const fs::path& p, const std::string& text) { io::write_file_atomically(p, text); }

/// Names in `dir` that contain ".tmp-" (temporaries of atomic writes).
inline std::vector<std::string> temporaries(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp-") != std::string::npos) out.push_back(e.path().filename().string());
  return out;
}

/// How many SIGKILLs a fault test sends: `quick` in ctest, or HULA_FAULT_KILLS when that is larger (the nightly
/// mode, docs/testing.md: HULA_FAULT_KILLS=100).
inline int fault_kills(int quick) {
  const char* v = std::getenv("HULA_FAULT_KILLS");
  const int asked = v != nullptr ? std::atoi(v) : 0;  // NOLINT(cert-err34-c): not a number is 0, the quick mode
  return asked > quick ? asked : quick;
}

/// A small 3-D point set as CSV.
inline const char* kPointsCsv = "0,0,0\n1,2,0\n3,3,1\n4,1,2\n6,0,2\n";

}  // namespace hula::regress
