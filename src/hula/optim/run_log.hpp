// SPDX-License-Identifier: MIT
// The run log (thesis 8.2.1 convergence graphs, appendix 6 experiments): every
// individual's variables, objectives, constraint violation and fitness for
// every generation, streamed to a callback (the UI's live convergence graph)
// and collectable into a RunLog that writes CSV or JSON with doubles printed
// to round-trip exactly (shortest std::to_chars form).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <span>
#include <utility>
#include <vector>

namespace hula::optim {

/// One generation's population, row-major. Generation 0 is the initial
/// population; for NSGA-II each later entry is the population after survival.
struct GenerationLog {
  /// Generation index, 0 = initial population.
  std::size_t generation = 0;
  /// Evaluations so far, this generation included.
  std::size_t evaluations = 0;
  /// Number of design variables per individual.
  std::size_t dimension = 0;
  /// Number of objectives per individual.
  std::size_t objectives = 0;
  /// population x dimension design variables.
  std::vector<double> variables{};
  /// population x objectives objective values (NaN for failed evaluations).
  std::vector<double> objective_values{};
  /// population constraint violations (0 = feasible, NaN if failed).
  std::vector<double> violation{};
  /// population fitness values: for the GAs the selection fitness (binary GA:
  /// (1/(1+e))^power, eq. 32-33), for NSGA-II the non-domination rank (0 = first front).
  std::vector<double> fitness{};
  /// population flags, 1 for a failed evaluation.
  std::vector<std::uint8_t> failed{};

  /// Number of individuals.
  [[nodiscard]] std::size_t size() const noexcept { return failed.size(); }
  /// Bitwise equality (NaN equals NaN), used by determinism tests.
  friend bool operator==(const GenerationLog& a, const GenerationLog& b) noexcept;
};

/// Callback receiving each generation as soon as it is complete. The reference
/// is valid only during the call.
using GenerationCallback = std::function<void(const GenerationLog&)>;

/// Convergence statistics of one generation (thesis 10.1: "best, mean, spread").
struct GenerationStatistics {
  /// Generation index.
  std::size_t generation = 0;
  /// Smallest finite value of objective 0 among feasible individuals (NaN if none).
  double best = 0.0;
  /// Mean of the finite values of objective 0.
  double mean = 0.0;
  /// Standard deviation of the finite values of objective 0.
  double spread = 0.0;
  /// Number of feasible, successfully evaluated individuals.
  std::size_t feasible = 0;
};

/// Statistics of objective 0 in one generation.
/// @param generation a logged generation.
/// @returns best (feasible), mean and spread of the successful evaluations.
[[nodiscard]] GenerationStatistics statistics(const GenerationLog& generation) noexcept;

/// The two run-log file formats.
enum class RunLogFormat { Csv, Json };

/// Writes a run log generation by generation as the run goes (bounded
/// memory: nothing is kept), in the formats RunLog::write_csv / write_json
/// describe. Write errors are the stream's (its badbit); the caller checks.
class RunLogWriter {
 public:
  /// @param out the stream, owned by the caller, outliving the writer
  /// @param format CSV or JSON
  RunLogWriter(std::ostream& out, RunLogFormat format);
  /// Writes one generation (the CSV header before the first).
  void append(const GenerationLog& generation);
  /// Ends the document (closes the JSON arrays); call once after the last append.
  void finish();
  /// Generations written so far.
  [[nodiscard]] std::size_t generations() const noexcept { return count_; }

 private:
  std::ostream* out_;
  RunLogFormat format_;
  std::size_t count_ = 0;
};

/// A whole run's log, collected from the callback.
class RunLog {
 public:
  /// Appends a copy of one generation.
  /// @param generation the generation to copy.
  void append(const GenerationLog& generation) { generations_.push_back(generation); }
  /// Appends one generation, moved in.
  void append(GenerationLog&& generation) { generations_.push_back(std::move(generation)); }
  /// A callback that appends to this log; the log must outlive the run.
  [[nodiscard]] GenerationCallback collector() {
    return [this](const GenerationLog& g) { append(g); };
  }
  /// The generations in order.
  [[nodiscard]] const std::vector<GenerationLog>& generations() const noexcept { return generations_; }
  /// Writes CSV with header `generation,evaluations,individual,x0..,f0..,violation,fitness,failed`.
  /// @param out the stream; the caller owns the file.
  void write_csv(std::ostream& out) const;
  /// Writes JSON `{"generations":[{"generation":g,"evaluations":e,"individuals":[{"variables":[..],
  /// "objectives":[..],"violation":v,"fitness":f,"failed":false},..]},..]}`; NaN is written as null.
  void write_json(std::ostream& out) const;
  /// Bitwise equality of every generation.
  friend bool operator==(const RunLog& a, const RunLog& b) noexcept { return a.generations_ == b.generations_; }

 private:
  std::vector<GenerationLog> generations_;
};

}  // namespace hula::optim
