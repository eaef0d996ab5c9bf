// SPDX-License-Identifier: MIT
#include "commands/study_common.hpp"

#include <sstream>
#include <system_error>

#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"

namespace hula::cli {

void add_study_options(CLI::App* sub, StudyArgs& args) {
  sub->add_option("study", args.study, "Study file (JSON, docs/formats.md \"Study files\")")->required();
  sub->add_option("--seed", args.seed, "Seed of the random streams (overrides the study file's \"seed\")");
  sub->add_option("--threads", args.threads,
                  "Worker threads, 0 = all cores (overrides the file's \"threads\"; results do not depend on it)");
  sub->add_option("--log", args.log, "Write the per-generation run log here (CSV if it ends in .csv, else JSON)");
  sub->add_option("--svg", args.svg, "Write the before/after figures and convergence graphs into this directory");
}

io::StudyDocument load_study(const StudyArgs& args, std::string_view kind) {
  io::StudyDocument doc = io::read_study_file(args.study, kind);
  if (args.seed) doc.header.seed = *args.seed;
  if (args.threads) doc.header.threads = *args.threads;
  return doc;
}

void write_svg(const std::filesystem::path& dir, std::string_view name, const io::SvgFigure& figure) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error(Errc::IoError, "cannot create the --svg directory '" + dir.string() + "': " + ec.message());
  io::write_file_atomically(dir / (std::string(name) + ".svg"), figure.render());
}

void write_run_log(const optim::RunLog& log, const std::filesystem::path& path) {
  std::ostringstream text;
  if (path.extension() == ".csv") {
    log.write_csv(text);
  } else {
    log.write_json(text);
  }
  io::write_file_atomically(path, text.str());
}

}  // namespace hula::cli
