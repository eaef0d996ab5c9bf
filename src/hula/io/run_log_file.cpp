// SPDX-License-Identifier: MIT
// Run log files (run_log_file.hpp).
#include "hula/io/run_log_file.hpp"

namespace hula::io {

optim::RunLogFormat run_log_format(const std::filesystem::path& path) {
  return path.extension() == ".csv" ? optim::RunLogFormat::Csv : optim::RunLogFormat::Json;
}

RunLogFile::RunLogFile(const std::filesystem::path& path, std::string_view option)
    : file_(path, option), writer_(file_.stream(), run_log_format(path)) {}

void RunLogFile::append(const optim::GenerationLog& generation) { writer_.append(generation); }

void RunLogFile::commit() {
  writer_.finish();
  file_.commit();
}

void write_run_log_file(const optim::RunLog& log, const std::filesystem::path& path, std::string_view option) {
  RunLogFile file(path, option);
  for (const optim::GenerationLog& g : log.generations()) file.append(g);
  file.commit();
}

}  // namespace hula::io
