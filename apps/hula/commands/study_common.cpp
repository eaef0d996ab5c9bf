// SPDX-License-Identifier: MIT
#include "commands/study_common.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <iostream>
#include <limits>
#include <system_error>

#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/optimise_request.hpp"
#include "hula/oli/fairing_baselines.hpp"

namespace hula::cli {

namespace {
// The token the SIGINT handler sets. A lock-free atomic store is
// async-signal-safe; a lock-based one would not be.
static_assert(std::atomic<bool>::is_always_lock_free, "the SIGINT handler needs a lock-free atomic flag");
optim::CancellationToken g_interrupt;

extern "C" void on_sigint(int /*signal*/) { g_interrupt.cancel(); }
}  // namespace

const optim::CancellationToken& interrupt_token() { return g_interrupt; }

InterruptGuard::InterruptGuard() {
  struct sigaction action {};
  action.sa_handler = on_sigint;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;  // a second Ctrl-C is not caught: it ends the process
  installed_ = ::sigaction(SIGINT, &action, &previous_) == 0;
}

InterruptGuard::~InterruptGuard() {
  if (installed_) ::sigaction(SIGINT, &previous_, nullptr);
}

void add_study_options(CLI::App* sub, StudyArgs& args, bool has_optimiser) {
  sub->add_option("study", args.study, "Study file (JSON, docs/formats.md \"Study files\")")->required();
  add_integer_option(sub, "--seed", args.seed, 0, kMaxSeed,
                     "Seed of the random streams in [0, 2^63-1] (overrides the study file's \"seed\")");
  add_integer_option(sub, "--threads", args.threads, 0, kMaxThreads,
                     "Worker threads, 0 = all cores (overrides the file's \"threads\"; results do not depend on it)");
  if (has_optimiser)
    add_real_option(sub, "--time", args.time, 0.0, std::numeric_limits<double>::max(), true,
                    "Wall-time limit of the whole run in seconds (every optimiser and round), > 0 (default: none); "
                    "ends with the best so far, as Ctrl-C does");
  sub->add_option("--log", args.log, "Write the per-generation run log here (CSV if it ends in .csv, else JSON)");
  sub->add_option("--svg", args.svg, "Write the before/after figures and convergence graphs into this directory");
}

void check_svg_directory(const std::filesystem::path& dir) {
  struct stat st {};
  if (::lstat(dir.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode))
      throw Error(Errc::IoError, "--svg: '" + dir.string() + "' exists and is not a directory", {.field = "svg"});
    if (::access(dir.c_str(), W_OK | X_OK) != 0)
      throw Error(Errc::IoError, "--svg: cannot create files in '" + dir.string() + "': " + std::strerror(errno),
                  {.field = "svg"});
    // The figures (and tables) a command writes here are replaced one by one after its computation:
    // each one already present must pass the output-path policy now, so a symbolic link, FIFO or
    // directory named like a figure stops the command before it computes anything.
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
      const std::string ext = entry.path().extension().string();
      if (ext == ".svg" || ext == ".csv") io::check_output_path(entry.path(), "--svg");
    }
    return;
  }
  // Absent: created later, so its nearest existing ancestor must be a writable directory. A trailing
  // separator ("out/", as the docs write it) names the same directory: its parent is that of "out".
  std::filesystem::path target = dir;
  while (!target.has_filename() && target.has_parent_path() && target != target.root_path())
    target = target.parent_path();
  std::filesystem::path parent = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  while (::stat(parent.c_str(), &st) != 0 && parent.has_parent_path() && parent != parent.parent_path())
    parent = parent.parent_path();
  if (::stat(parent.c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || ::access(parent.c_str(), W_OK | X_OK) != 0)
    throw Error(Errc::IoError, "--svg: cannot create the directory '" + dir.string() + "'", {.field = "svg"});
}

TerminalProgress::TerminalProgress(std::vector<double> reference, bool enabled)
    : active_(enabled && ::isatty(STDERR_FILENO) == 1), reference_(std::move(reference)) {}

TerminalProgress::~TerminalProgress() {
  try {
    finish();
  } catch (...) {  // a failing terminal leaves nothing to report the progress to
  }
}

void TerminalProgress::finish() {
  if (!active_) return;
  if (pending_)
    draw(io::generation_progress_line(*pending_, reference_));
  else if (pending_line_)
    draw(*pending_line_);
  if (drawn_) std::cerr << '\n' << std::flush;
  active_ = false;
}

bool TerminalProgress::too_soon() const {
  constexpr auto kRedraw = std::chrono::milliseconds(100);
  return drawn_ && std::chrono::steady_clock::now() - last_ < kRedraw;
}

void TerminalProgress::show(const optim::GenerationLog& g) {
  if (!active_) return;
  if (too_soon()) {
    pending_ = g;
    pending_line_.reset();
    return;
  }
  draw(io::generation_progress_line(g, reference_));
}

void TerminalProgress::show(std::string line) {
  if (!active_) return;
  if (too_soon()) {
    pending_line_ = std::move(line);
    pending_.reset();
    return;
  }
  draw(line);
}

void TerminalProgress::print(const std::string& text) {
  if (!active_) {
    std::cerr << text << '\n' << std::flush;
    return;
  }
  // Erase the progress line, write the text on it, and draw the progress line again below.
  std::cerr << "\r\x1b[K" << text << '\n';
  if (drawn_) std::cerr << line_ << "\x1b[K";
  std::cerr << std::flush;
}

void TerminalProgress::draw(const std::string& line) {
  // Carriage return, the line, erase to the end of the line: the line is redrawn in place.
  std::cerr << '\r' << line << "\x1b[K" << std::flush;
  line_ = line;
  drawn_ = true;
  pending_.reset();
  pending_line_.reset();
  last_ = std::chrono::steady_clock::now();
}

io::StudyDocument load_study(const StudyArgs& args, std::string_view kind) {
  // Every output is checked before the study runs, not after.
  if (args.log) io::check_output_path(*args.log, "--log");
  if (args.svg) check_svg_directory(*args.svg);
  io::StudyDocument doc = io::read_study_file(args.study, kind);
  if (args.seed) doc.header.seed = *args.seed;
  if (args.threads) doc.header.threads = *args.threads;
  return doc;
}

oli::StudyOutcome run_study_command(const StudyArgs& args, std::string_view kind,
                                    const std::vector<StudyOverride>& overrides) {
  io::StudyDocument doc = load_study(args, kind);
  for (const StudyOverride& o : overrides) doc.body[o.member] = o.value;
  oli::StudyRunOptions options;
  options.wall_time_seconds = args.time.value_or(0.0);
  options.cancel = &interrupt_token();
  options.keep_log = args.log.has_value();
  TerminalProgress progress;
  if (progress.active()) options.on_generation = [&progress](const optim::GenerationLog& g) { progress.show(g); };
  oli::StudyOutcome outcome;
  try {
    const InterruptGuard guard;  // Ctrl-C ends the optimisers with their best so far, as --time does
    outcome = oli::run_study(doc, io::relative_to(std::filesystem::path(args.study).parent_path()), options);
  } catch (const Error& e) {
    for (const StudyOverride& o : overrides)
      if (e.where().field == o.member) throw Error(e.code(), o.flag + ": " + e.message(), {.field = o.flag});
    throw;
  }
  if (args.svg) {
    const io::StudyFigures figures = oli::study_figures(outcome);
    for (const io::NamedFigure& f : figures.figures) write_svg(*args.svg, f.name, f.figure);
    for (const io::NamedTable& t : figures.tables)
      io::write_file_atomically(std::filesystem::path(*args.svg) / t.name, t.text);
  }
  return outcome;
}

Json occt_baselines(const oli::StudyOutcome& run, const StudyArgs& args) {
  oli::FairingBaselines b;
  try {
    b = oli::fairing_baselines(run);
  } catch (const Error& e) {
    if (e.where().field != "occt") throw;
    throw Error(e.code(), "--occt: " + e.message(), {.field = "--occt"});
  }
  if (args.svg) write_svg(*args.svg, "baselines", b.figure);
  return std::move(b.json);
}

void write_svg(const std::filesystem::path& dir, std::string_view name, const io::SvgFigure& figure) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error(Errc::IoError, "cannot create the --svg directory '" + dir.string() + "': " + ec.message());
  io::write_file_atomically(dir / (std::string(name) + ".svg"), figure.render());
}

void record_run(Json& output, const StudyArgs& args) {
  output["log"] = args.log ? Json(*args.log) : Json(nullptr);
  if (args.log) io::write_file_atomically(*args.log, io::to_file_text(output));
}

}  // namespace hula::cli
