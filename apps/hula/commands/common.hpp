// SPDX-License-Identifier: MIT
// Shared pieces of the `hula` commands: the exit-code table, JSON output,
// parsing of command-line lists and end conditions (with hula::Error naming
// the option; the lists and end conditions are io's readers). The commands
// translate arguments into io/oli requests and print the answers.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/option_text.hpp"
#include "hula/io/table_text.hpp"

namespace hula::cli {

using Json = io::Json;

/// Exit codes of `hula` (documented in docs/cli.md, docs/errors.md and `hula --help`).
enum ExitCode : int {
  kExitOk = 0,            ///< success; the result JSON is on stdout
  kExitUsage = 2,         ///< bad command line (unknown option, missing argument, a number out of range)
  kExitInvalidInput = 3,  ///< hula::Error other than NumericalFailure: bad file, bad value, I/O failure
                          ///< (including a standard output that cannot be written)
  kExitNumerical = 4,     ///< hula::Error(NumericalFailure): overflow or no convergence
  kExitInternal = 5,      ///< a bug in hula (InternalError or an unexpected exception)
  kExitOutOfMemory = 6,   ///< memory ran out (or an address-space limit was reached)
};

/// Documented upper bounds of the sizes the command line accepts (docs/cli.md
/// "Limits"): within them a run needs at most a few GB; beyond them it is
/// refused before it starts instead of running out of memory half-way.
inline constexpr long long kMaxPopulation = 1'000'000;
inline constexpr long long kMaxGenerations = 100'000'000;
inline constexpr long long kMaxEvaluations = 1'000'000'000'000;
inline constexpr long long kMaxDimension = 100'000;
inline constexpr long long kMaxObjectives = 64;
inline constexpr long long kMaxSamples = 1'000'000;
inline constexpr long long kMaxThreads = 1024;
/// The largest seed: seeds are signed 64-bit on the command line and in files.
inline constexpr long long kMaxSeed = 9'223'372'036'854'775'807;

/// Adds --format json|jsonl|csv|text (default json) to a command that prints records; `records` says
/// what one record is in the help ("one sample per line").
CLI::Option* add_format_option(CLI::App* sub, std::string& format, const std::string& records);
/// Shows `choices` as the option's value set ("TEXT:{a,b}" in --help, the values `hula completion bash`
/// completes) without checking them: the option's reader checks the value and names what it accepts.
CLI::Option* set_choices(CLI::Option* option, const std::vector<std::string>& choices);
/// Prints `document` (--format json) or the table `make_table` builds from it (jsonl, csv, text:
/// io::format_table, the one table writer).
void print_formatted(const Json& document, std::string_view format,
                     const std::function<io::Table(const Json&)>& make_table);

/// Prints a JSON document on stdout (io::format_json: 2-space indentation,
/// arrays of numbers on one line, no -0.0, final newline).
/// @throws hula::Error(Errc::IoError) when standard output cannot be written (exit 3)
void print_json(const Json& document);
/// Prints the command's JSON result, unless its -o/--output is `-`: then the
/// written file is what stdout carries (a pipe to the next command), alone.
void print_result(const Json& document, std::string_view output);
/// Prints text on stdout, checked like print_json.
void print_text(std::string_view text);

/// Parses an integer option as signed 64-bit and checks it is in [lo, hi]
/// (and even when `even`). The message quotes the flag and what the user typed:
/// "--population -5: must be an even number in [2, 1000000]".
/// @throws CLI::ValidationError (exit 2, usage)
[[nodiscard]] long long parse_integer_option(std::string_view text, std::string_view flag, long long lo, long long hi,
                                             bool even = false);
/// Parses a finite real option in [lo, hi] (lo excluded when `lo_open`).
/// @throws CLI::ValidationError "--time 0: must be a number > 0" (exit 2, usage)
[[nodiscard]] double parse_real_option(std::string_view text, std::string_view flag, double lo, double hi,
                                       bool lo_open = false);

/// Adds an integer option parsed by parse_integer_option into `target`.
template <class T>
CLI::Option* add_integer_option(CLI::App* sub, const std::string& flags, std::optional<T>& target, long long lo,
                                long long hi, const std::string& help, bool even = false) {
  const std::string flag = "--" + flags.substr(flags.rfind("--") + 2);
  return sub
      ->add_option_function<std::string>(
          flags,
          [&target, flag, lo, hi, even](const std::string& text) {
            target = static_cast<T>(parse_integer_option(text, flag, lo, hi, even));
          },
          help)
      ->type_name("INT");
}
/// Adds a real option parsed by parse_real_option into `target`.
CLI::Option* add_real_option(CLI::App* sub, const std::string& flags, std::optional<double>& target, double lo,
                             double hi, bool lo_open, const std::string& help);

/// Adds the options of a command that writes an exact (natural) curve: -o,--output FILE, --to-nurbs TOL
/// (write its NURBS within TOL instead of its laws) and --tolerance T (the integration's position tolerance,
/// default curve::kNaturalTolerance).
void add_exact_output_options(CLI::App* sub, std::string& output, std::optional<double>& to_nurbs, double& tolerance);
/// Comma-separated numbers and end conditions as io reads them (io/option_text.hpp).
using io::parse_end_condition;
using io::parse_number_list;

/// A registered subcommand and the function that runs it after parsing
/// (returns the exit code; hula::Error propagates to main).
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

/// `hula interpolate`: points file -> cubic spline curve file.
[[nodiscard]] Command add_interpolate(CLI::App& app);
/// `hula eval`: positions and derivatives at parameters.
[[nodiscard]] Command add_eval(CLI::App& app);
/// `hula analyse`: Frenet/Bishop frames, curvature, torsion and speed of a curve file.
[[nodiscard]] Command add_analyse(CLI::App& app);
/// `hula law`: evaluate, differentiate and analyse a law expression.
[[nodiscard]] Command add_law(CLI::App& app);
/// `hula serve`: the local HTTP JSON API.
[[nodiscard]] Command add_serve(CLI::App& app);
/// `hula reconstruct`: a curve from its curvature and torsion laws (natural equations).
[[nodiscard]] Command add_reconstruct(CLI::App& app);
/// `hula info`: the analysis of a curve file.
[[nodiscard]] Command add_info(CLI::App& app);
/// `hula demo`: the thesis's example curves.
[[nodiscard]] Command add_demo(CLI::App& app);
/// `hula optimise`: a GA, NSGA-II or pagmo2 algorithm on a test problem or problem file.
[[nodiscard]] Command add_optimise(CLI::App& app);
/// `hula batch`: a campaign of study runs (commands/batch.cpp).
[[nodiscard]] Command add_batch(CLI::App& app);
/// `hula fair-knots`: knot-vector studies of thesis 7.2-7.4 from a "fair-knots" study file.
[[nodiscard]] Command add_fair_knots(CLI::App& app);
/// `hula fin-compound`: prescribed compound fins (projection technique, Combescure transform).
[[nodiscard]] Command add_fin_compound(CLI::App& app);
/// `hula edit-projection`: rebuild a 3-D curve from an edited projection.
[[nodiscard]] Command add_edit_projection(CLI::App& app);
/// `hula hermite`: Hermite editing of a spline's tangent and normal handles.
[[nodiscard]] Command add_hermite(CLI::App& app);
/// `hula match-curvature`: a prescribed curvature profile matched over data points (GA or hybrid).
[[nodiscard]] Command add_match_curvature(CLI::App& app);
/// `hula match-curvature-torsion`: curvature and torsion profiles as two objectives (NSGA-II).
[[nodiscard]] Command add_match_curvature_torsion(CLI::App& app);
/// `hula edit insert-knot|refine|elevate|split|reverse|reparam`: kernel edits of a NURBS curve file.
[[nodiscard]] Command add_edit(CLI::App& app);
/// `hula approximate`: least-squares fit within a tolerance (fewest control points).
[[nodiscard]] Command add_approximate(CLI::App& app);
/// `hula closest`: nearest points of a curve.
[[nodiscard]] Command add_closest(CLI::App& app);
/// `hula clothoid`: G1 / G2 Hermite interpolation by clothoids.
[[nodiscard]] Command add_clothoid(CLI::App& app);
[[nodiscard]] Command add_log_aesthetic(CLI::App& app);
/// `hula deviation`: distance between two curves.
[[nodiscard]] Command add_deviation(CLI::App& app);
/// `hula continuity`: continuity of the join of two curves.
[[nodiscard]] Command add_continuity(CLI::App& app);
/// `hula energy`: bending and curvature-variation energies.
[[nodiscard]] Command add_energy(CLI::App& app);
/// `hula match`: A's end made G0-G3 to B.
[[nodiscard]] Command add_match(CLI::App& app);
/// `hula blend`: a fair G1-G3 blend between two curve ends.
[[nodiscard]] Command add_blend(CLI::App& app);
/// `hula convert`: curves between JSON, STEP, IGES, DXF and SVG.
[[nodiscard]] Command add_convert(CLI::App& app);
/// `hula completion bash|man`: the completion script and the man pages, generated from the registered commands.
[[nodiscard]] Command add_completion(CLI::App& app);
/// "; did you mean `hula interpolate`?" (or "; did you mean --samples?") for the first word of the command
/// line that names no command or option of `root` but is near one; empty when there is none.
[[nodiscard]] std::string did_you_mean(const CLI::App& root, int argc, char** argv);
/// Runs the demo and prints its JSON.
int run_demo();

}  // namespace hula::cli
