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

  CLI::App app{"hula: HulaHoops NURBS curve workbench", "hula"};
  app.set_version_flag("--version", std::string("hula ") + HULA_VERSION);
  app.footer(kFooter);
  app.require_subcommand(0, 1);
  app.fallthrough();
  std::string error_format_name;
  app.add_option("--error-format", error_format_name,
                 "How errors are printed on stderr: text (one line) or json (default: text on a terminal, else json)")
      ->check(CLI::IsMember({"text", "json"}));
  try {
    std::vector<hula::cli::Command> commands = {
        hula::cli::add_interpolate(app),
        hula::cli::add_eval(app),
        hula::cli::add_info(app),
        hula::cli::add_demo(app),
        hula::cli::add_law(app),
        hula::cli::add_analyse(app),
        hula::cli::add_reconstruct(app),
        hula::cli::add_optimise(app),
        hula::cli::add_fair_knots(app),
        hula::cli::add_fin_compound(app),
        hula::cli::add_edit_projection(app),
        hula::cli::add_hermite(app),
        hula::cli::add_match_curvature(app),
        hula::cli::add_match_curvature_torsion(app),
        hula::cli::add_doc(app),
        hula::cli::add_convert(app),
        hula::cli::add_edit(app),
        hula::cli::add_approximate(app),
        hula::cli::add_fit(app),
        hula::cli::add_closest(app),
        hula::cli::add_intersect(app),
        hula::cli::add_distance(app),
        hula::cli::add_offset(app),
        hula::cli::add_helical_offset(app),
        hula::cli::add_orthotomic(app),
        hula::cli::add_polar(app),
        hula::cli::add_hermite_frenet(app),
        hula::cli::add_clothoid(app),
        hula::cli::add_log_aesthetic(app),
        hula::cli::add_deviation(app),
        hula::cli::add_continuity(app),
        hula::cli::add_energy(app),
        hula::cli::add_match(app),
        hula::cli::add_blend(app),
        hula::cli::add_serve(app),
        hula::cli::add_batch(app),
    };
    commands.push_back(hula::cli::add_completion(app));
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
