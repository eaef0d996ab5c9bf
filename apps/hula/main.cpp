// SPDX-License-Identifier: MIT
// `hula`: the HulaHoops command line. Thin: parses the command line (CLI11),
// calls the pure kernel and io functions, prints JSON on stdout, and turns
// errors into an exit code plus a message on stderr (DESIGN.md "Errors":
// boundaries turn hula::Error into a status). Errors are one readable line
// when stderr is a terminal and the error JSON otherwise, or as chosen with
// --error-format text|json.
//
// Exit codes: 0 ok; 2 usage (command-line errors, numbers out of range);
// 3 invalid input (any hula::Error except NumericalFailure, including
// IoError and a standard output that cannot be written); 4 numerical failure
// (hula::Error NumericalFailure); 5 internal error (a bug); 6 out of memory.
//
// SIGPIPE and SIGXFSZ are ignored so that a closed pipe or a file-size limit
// turns into a failed write(2) that is reported (exit 3), not a silent death.
// A closed standard descriptor (`>&-`) is reserved with /dev/null opened
// read-only, so that no file hula opens can take its number (output meant for
// stdout must never land in a curve file) and writes to it fail with EBADF.
//
// Under an MPI launcher (mpirun -np K and the like), a command that does not
// use MPI — every command of a build without MPI — would run K times with
// interleaved output: it is refused instead (Unsupported, exit 3).
#include <fcntl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <array>
#include <cctype>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "commands/common.hpp"
#include "commands/doc.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/error_json.hpp"
#include "hula/io/json_write.hpp"
#include "hula/oli/process_ranks.hpp"

namespace hula::cli {
/// `hula fit` (commands/fit.cpp): scanned points or a "fit" study -> faired class-A curve, strays, figures.
[[nodiscard]] Command add_fit(CLI::App& app);
/// `hula intersect` (commands/intersect.cpp): curve–curve and self-intersections.
[[nodiscard]] Command add_intersect(CLI::App& app);
/// `hula distance` (commands/intersect.cpp): the smallest distance between two curves.
[[nodiscard]] Command add_distance(CLI::App& app);
/// `hula offset` (commands/offset.cpp): planar offsets with cusps and loops trimmed.
[[nodiscard]] Command add_offset(CLI::App& app);
/// `hula helical-offset` (commands/offset.cpp): helical offsets in the Frenet or Bishop frame.
[[nodiscard]] Command add_helical_offset(CLI::App& app);
/// `hula orthotomic` and `hula polar` (commands/mapping.cpp): the mapping techniques of thesis 6.3.2.
[[nodiscard]] Command add_orthotomic(CLI::App& app);
[[nodiscard]] Command add_polar(CLI::App& app);
/// `hula hermite-frenet` (commands/hermite.cpp): Hermite handles with normal and binormal (torsion) constraints.
[[nodiscard]] Command add_hermite_frenet(CLI::App& app);
}  // namespace hula::cli

#ifndef HULA_VERSION
#define HULA_VERSION "unknown"
#endif

namespace {

using hula::cli::Json;

enum class ErrorFormat { Text, JsonDocument };

ErrorFormat g_error_format = ErrorFormat::JsonDocument;

// The --error-format value, read from argv before CLI11 parses (usage errors
// are reported in the chosen format too); default: text on a terminal.
ErrorFormat error_format_from_argv(int argc, char** argv) {
  ErrorFormat format = ::isatty(STDERR_FILENO) == 1 ? ErrorFormat::Text : ErrorFormat::JsonDocument;
  for (int i = 1; i < argc; ++i) {
    std::string_view arg = argv[i];
    std::string_view value;
    if (arg == "--error-format" && i + 1 < argc)
      value = argv[i + 1];
    else if (arg.starts_with("--error-format="))
      value = arg.substr(std::string_view("--error-format=").size());
    if (value == "text") format = ErrorFormat::Text;
    if (value == "json") format = ErrorFormat::JsonDocument;
  }
  return format;
}

// Writes the error on stderr; a failing stderr leaves nothing else to report to.
void print_error(const Json& error) {
  std::string text;
  if (g_error_format == ErrorFormat::JsonDocument) {
    text = hula::io::format_json(error);
  } else {
    const Json& body = error["error"];
    text = "hula: error: " + body.value("message", std::string()) + " [" + body.value("code", std::string()) + "]\n";
  }
  std::cout.flush();
  std::cerr << text;
  std::cerr.flush();
}

Json plain_error(const std::string& code, const std::string& message, const std::string& field = {}) {
  Json body = Json::object();
  body["code"] = code;
  body["message"] = message;
  body["where"] = Json::object();
  if (!field.empty()) body["where"]["field"] = field;
  Json out = Json::object();
  out["error"] = std::move(body);
  return out;
}

// The option a usage message is about: its first "--name" (the option's checks and CLI11 name it
// first, "--tolerance 0: must be a number > 0"), without the dashes, as where.field of other errors.
std::string option_in(std::string_view message) {
  const std::size_t at = message.find("--");
  if (at == std::string_view::npos) return {};
  std::size_t end = at + 2;
  while (end < message.size() && (std::isalnum(static_cast<unsigned char>(message[end])) || message[end] == '-')) ++end;
  return std::string(message.substr(at + 2, end - at - 2));
}

constexpr const char* kVersion = "hula " HULA_VERSION;

constexpr const char* kFooter =
    "Files: every input file may be - (standard input) and every -o/--output - (standard output).\n"
    "Output: JSON on stdout. Errors: one line on a terminal, else {\"error\": {\"code\", \"message\", \"where\"}}\n"
    "on stderr (--error-format text|json chooses).\n"
    "Exit codes: 0 ok, 2 usage error, 3 invalid input (including unreadable or unwritable files and a failing\n"
    "standard output), 4 numerical failure, 5 internal error, 6 out of memory.";

// Prints the help text (plain `hula`, `hula --help`), checked like any output.
int print_help(const CLI::App& app) {
  hula::cli::print_text(app.help());
  return hula::cli::kExitOk;
}

// Prints what CLI11 prints for --help, --help-all or --version, checked like any output (a failing
// stdout, e.g. /dev/full, is exit 3, not a silent 0).
int print_exit_text(const CLI::App& app, const CLI::Error& e) {
  std::ostringstream out, err;
  const int code = app.exit(e, out, err);
  hula::cli::print_text(out.str());
  if (!err.str().empty()) std::cerr << err.str();
  return code;
}

// How many copies an MPI launcher started, from its environment (Open MPI's OMPI_COMM_WORLD_SIZE, PMI_SIZE of
// MPICH and Slurm, PMIX_SIZE; a rank variable above 0 means at least two), with the variable that says so; 1 and
// "" outside a launcher.
std::pair<long, std::string> launcher_copies() {
  const auto number = [](const char* name) -> long {
    const char* v = std::getenv(name);
    if (v == nullptr) return -1;
    char* end = nullptr;
    const long n = std::strtol(v, &end, 10);
    return end != v ? n : -1;
  };
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const long n = number(name); n > 1) return {n, std::string(name) + "=" + std::to_string(n)};
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
    if (const long n = number(name); n > 0) return {2, std::string(name) + "=" + std::to_string(n)};
  return {1, ""};
}

// Refuses to run `command` as one of several copies an MPI launcher started, unless it uses MPI (batch, and
// optimise with --islands, in a build with MPI).
void refuse_copies_under_mpi_launcher(const CLI::App& command) {
  const auto [copies, variable] = launcher_copies();
  if (copies <= 1) return;
  const std::string name = command.get_name();
  const bool mpi = hula::oli::runs_mpi();
  if (mpi && (name == "batch" || (name == "optimise" && command.count("--islands") > 0))) return;
  const std::string why = mpi ? "hula " + name + " does not use MPI" : "this hula was built without MPI (HULA_MPI=OFF)";
  const std::string fix =
      mpi ? "run it once, without the launcher" : "run it without the launcher, or use a hula built with -DHULA_MPI=ON";
  throw hula::Error(hula::Errc::Unsupported,
                    why + ", but an MPI launcher started it as one of several copies (" + variable +
                        "): each would run the whole command on its own, with interleaved output; " + fix,
                    hula::ErrorWhere{.field = "mpi"});
}

// The commands in the order `hula --help` lists them; `add` registers the one top-level command `name`.
struct CommandEntry {
  std::string_view name;
  hula::cli::Command (*add)(CLI::App&);
};
constexpr std::array<CommandEntry, 37> kCommands{{
    {"interpolate", hula::cli::add_interpolate},
    {"eval", hula::cli::add_eval},
    {"info", hula::cli::add_info},
    {"demo", hula::cli::add_demo},
    {"law", hula::cli::add_law},
    {"analyse", hula::cli::add_analyse},
    {"reconstruct", hula::cli::add_reconstruct},
    {"optimise", hula::cli::add_optimise},
    {"fair-knots", hula::cli::add_fair_knots},
    {"fin-compound", hula::cli::add_fin_compound},
    {"edit-projection", hula::cli::add_edit_projection},
    {"hermite", hula::cli::add_hermite},
    {"match-curvature", hula::cli::add_match_curvature},
    {"match-curvature-torsion", hula::cli::add_match_curvature_torsion},
    {"doc", hula::cli::add_doc},
    {"convert", hula::cli::add_convert},
    {"edit", hula::cli::add_edit},
    {"approximate", hula::cli::add_approximate},
    {"fit", hula::cli::add_fit},
    {"closest", hula::cli::add_closest},
    {"intersect", hula::cli::add_intersect},
    {"distance", hula::cli::add_distance},
    {"offset", hula::cli::add_offset},
    {"helical-offset", hula::cli::add_helical_offset},
    {"orthotomic", hula::cli::add_orthotomic},
    {"polar", hula::cli::add_polar},
    {"hermite-frenet", hula::cli::add_hermite_frenet},
    {"clothoid", hula::cli::add_clothoid},
    {"log-aesthetic", hula::cli::add_log_aesthetic},
    {"deviation", hula::cli::add_deviation},
    {"continuity", hula::cli::add_continuity},
    {"energy", hula::cli::add_energy},
    {"match", hula::cli::add_match},
    {"blend", hula::cli::add_blend},
    {"serve", hula::cli::add_serve},
    {"batch", hula::cli::add_batch},
    {"completion", hula::cli::add_completion},
}};

const CommandEntry* command_named(std::string_view word) {
  for (const CommandEntry& command : kCommands)
    if (command.name == word) return &command;
  return nullptr;
}

// The command to build alone: the first word of the command line, after --error-format and its value only,
// when it names a command other than `completion` (which prints the whole tree) and no other word is the name
// of a command (a value that happens to be one, or a second command, is left to CLI11 with the whole tree).
// nullptr when the whole tree is needed: no command (`hula`, `hula --help`, `hula --version` with other
// words), an option before the command, or a misspelt command ("did you mean" compares it with every name).
const CommandEntry* command_to_build_alone(int argc, char** argv) {
  const CommandEntry* named = nullptr;
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (named != nullptr) {
      if (command_named(word) != nullptr) return nullptr;
      continue;
    }
    if (word == "--error-format") {
      if (i + 1 < argc && command_named(argv[i + 1]) != nullptr) return nullptr;
      ++i;
      continue;
    }
    if (word.starts_with("--error-format=")) continue;
    named = command_named(word);
    if (named == nullptr) return nullptr;
  }
  return named != nullptr && named->name != "completion" ? named : nullptr;
}
}  // namespace

int main(int argc, char** argv) {
  for (int fd = STDIN_FILENO; fd <= STDERR_FILENO; ++fd) {
    if (::fcntl(fd, F_GETFD) == -1) {
      const int reserved = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
      if (reserved >= 0 && reserved != fd) {
        ::dup2(reserved, fd);
        ::close(reserved);
      }
    }
  }
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
  g_error_format = error_format_from_argv(argc, argv);

  // `hula --version` alone: the text CLI11's version flag prints, without building the command tree (every
  // other spelling, `hula --error-format json --version` included, goes through CLI11 and prints the same).
  if (argc == 2 && std::string_view(argv[1]) == "--version") {
    try {
      hula::cli::print_text(std::string(kVersion) + "\n");
      return hula::cli::kExitOk;
    } catch (const hula::Error& e) {
      print_error(hula::io::error_to_json(e));
      return hula::cli::kExitInvalidInput;
    }
  }

  CLI::App app{"hula: HulaHoops NURBS curve workbench", "hula"};
  app.set_version_flag("--version", kVersion);
  app.footer(kFooter);
  app.require_subcommand(0, 1);
  app.fallthrough();
  std::string error_format_name;
  app.add_option("--error-format", error_format_name,
                 "How errors are printed on stderr: text (one line) or json (default: text on a terminal, else json)")
      ->check(CLI::IsMember({"text", "json"}));
  try {
    // Building CLI11's tree of every command and its options was most of the time `hula` spent in its own code
    // before running a command (docs/benchmarks.md, "Command-line start-up"): only the command named is built
    // when that parses the command line as the whole tree would.
    std::vector<hula::cli::Command> commands;
    if (const CommandEntry* alone = command_to_build_alone(argc, argv)) {
      commands.push_back(alone->add(app));
    } else {
      for (const CommandEntry& command : kCommands) commands.push_back(command.add(app));
    }
    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return print_exit_text(app, e);
    } catch (const CLI::CallForAllHelp& e) {
      return print_exit_text(app, e);
    } catch (const CLI::CallForVersion& e) {
      return print_exit_text(app, e);
    }
    // Pipes (`--points <(cat pts.csv)`, a named FIFO) are inputs like files for the commands typed in a
    // shell; `hula serve` never blocks on a path a request names.
    for (const auto& command : commands)
      if (command.app->parsed()) {
        hula::io::set_pipe_inputs(command.app->get_name() != "serve");
        refuse_copies_under_mpi_launcher(*command.app);
        return command.run();
      }
    return print_help(app);
  } catch (const CLI::ParseError& e) {
    print_error(plain_error("UsageError", std::string(e.what()) + hula::cli::did_you_mean(app, argc, argv),
                            option_in(e.what())));
    return hula::cli::kExitUsage;
  } catch (const hula::Error& e) {
    print_error(hula::io::error_to_json(e));
    return e.code() == hula::Errc::NumericalFailure ? hula::cli::kExitNumerical : hula::cli::kExitInvalidInput;
  } catch (const std::bad_alloc& e) {
    // No allocation-heavy work here: the message is short and the stack is unwound. A bad_alloc that
    // names what ran out (the exchange helper's, oli::ExchangeOutOfMemory) is reported as it says.
    const std::string what = e.what();
    print_error(plain_error(
        "OutOfMemory", what != std::bad_alloc().what()
                           ? "out of memory: " + what
                           : std::string("out of memory: the run needs more memory than the system (or its "
                                         "address-space limit) allows; reduce --population, --dimension, --samples "
                                         "or the input size (docs/cli.md \"Limits\")")));
    return hula::cli::kExitOutOfMemory;
  } catch (const std::length_error&) {
    print_error(plain_error("OutOfMemory", "out of memory: a requested size exceeds what can be allocated"));
    return hula::cli::kExitOutOfMemory;
  } catch (const std::exception& e) {
    print_error(plain_error("InternalError", e.what()));
    return hula::cli::kExitInternal;
  }
}
