// SPDX-License-Identifier: MIT
// The codec of an optimisation run report (optim::RunReport: the
// run report is written one way). Every run report the project prints or stores
// — `hula optimise` and `hula optimise --islands` ("report"), the server's
// problem jobs ("report"), the match studies ("ga", "nsga2") — is this object:
//   {"termination", "message", "generations", "evaluations",
//    "failed_evaluations", "seconds"}
// followed by the run's identity where the writer has it ("seed", "threads",
// "algorithm", "problem"). Member names are a contract (docs/formats.md,
// src/hula/server/openapi.json): extend, never rename.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "hula/io/json_curve.hpp"
#include "hula/optim/run_log.hpp"
#include "hula/optim/run_report.hpp"
#include "hula/studies/study.hpp"

namespace hula::io {

/// Who ran: the members written after the report, each only when set.
struct RunIdentity {
  std::optional<std::uint64_t> seed{};     ///< "seed"
  std::optional<std::size_t> threads{};    ///< "threads"
  std::optional<std::string> algorithm{};  ///< "algorithm"
  std::optional<std::string> problem{};    ///< "problem" (the problem's name)
};

/// A run report as JSON: the six report members in the order above, then the identity's set members.
[[nodiscard]] Json run_report_to_json(const optim::RunReport& report, const RunIdentity& identity = {});

/// Reads the report members back (the identity members and any others are ignored; "message" may be
/// absent, as in reports written before it was added to the match studies).
/// @throws hula::Error(Errc::ParseError) naming the member that is missing or mistyped, or an unknown
///   termination name
[[nodiscard]] optim::RunReport run_report_from_json(const Json& json);

/// A study run's report: {"study": kind, "termination": "Cancelled" or "Completed", "generations",
/// "evaluations", "seconds"} (the study job's "report", docs/server.md).
[[nodiscard]] Json study_report_to_json(const studies::StudyReport& report);

/// The progress event of one generation (a server job's "generation" event): {"generation", "evaluations",
/// "best": objectives of the best individual (feasible first, then smallest first objective; null for an
/// undefined value), "front" (several objectives: the first front's objectives, fitness = rank 0), "elapsed":
/// `elapsed` seconds}.
[[nodiscard]] Json generation_event_json(const optim::GenerationLog& generation, double elapsed);

/// A run log as a JSON value with the members optim::RunLog::write_json writes: {"generations":
/// [{"generation", "evaluations", "individuals": [{"variables", "objectives", "violation", "fitness",
/// "failed"}]}]}, NaN as null: the log a document stores with a study run.
[[nodiscard]] Json run_log_to_json(const optim::RunLog& log);

/// Reads run_log_to_json's form back (null as NaN): a study run's log in a document JSON file or in a
/// document stored before logs were stored as columns. Every individual of a generation has the same
/// numbers of variables and objectives.
/// @throws hula::Error(Errc::ParseError) naming the member ("log.generations[2].individuals[5].fitness")
///   that is missing, mistyped or unknown, or whose count differs from the generation's first individual
[[nodiscard]] optim::RunLog run_log_from_json(const Json& json);

}  // namespace hula::io
