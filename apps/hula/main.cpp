// SPDX-License-Identifier: MIT
// `hula`: the HulaHoops command line. Thin: parses the command line (CLI11),
// calls the pure kernel and io functions, prints machine-readable JSON on
// stdout, and turns errors into an exit code plus the error JSON on stderr
// (DESIGN.md "Errors": boundaries turn hula::Error into a status).
//
// Exit codes: 0 ok; 2 usage (command-line errors); 3 invalid input (any
// hula::Error except NumericalFailure, including IoError); 4 numerical
// failure (hula::Error NumericalFailure); 5 internal error (a bug).
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <vector>

#include "commands/common.hpp"
#include "commands/doc.hpp"
#include "hula/core/error.hpp"
#include "hula/io/error_json.hpp"

#ifndef HULA_VERSION
#define HULA_VERSION "unknown"
#endif

namespace {

using hula::cli::Json;

void print_error(const Json& error) {
  std::cerr << error.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
  std::cerr.flush();
}

Json plain_error(const std::string& code, const std::string& message) {
  Json body = Json::object();
  body["code"] = code;
  body["message"] = message;
  body["where"] = Json::object();
  Json out = Json::object();
  out["error"] = std::move(body);
  return out;
}

constexpr const char* kFooter =
    "Output: JSON on stdout. Errors: {\"error\": {\"code\", \"message\", \"where\"}} on stderr.\n"
    "Exit codes: 0 ok, 2 usage error, 3 invalid input (including unreadable or unwritable files),\n"
    "4 numerical failure, 5 internal error.";

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hula: HulaHoops NURBS curve workbench (default command: demo)", "hula"};
  app.set_version_flag("--version", std::string("hula ") + HULA_VERSION);
  app.footer(kFooter);
  app.require_subcommand(0, 1);
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
      hula::cli::add_batch(app),
      hula::cli::add_doc(app),
  };
  try {
    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
      return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
      return app.exit(e);
    } catch (const CLI::ParseError& e) {
      print_error(plain_error("UsageError", e.what()));
      return hula::cli::kExitUsage;
    }
    for (const auto& command : commands)
      if (command.app->parsed()) return command.run();
    return hula::cli::run_demo();
  } catch (const hula::Error& e) {
    print_error(hula::io::error_to_json(e));
    return e.code() == hula::Errc::NumericalFailure ? hula::cli::kExitNumerical : hula::cli::kExitInvalidInput;
  } catch (const std::exception& e) {
    print_error(plain_error("InternalError", e.what()));
    return hula::cli::kExitInternal;
  }
}
