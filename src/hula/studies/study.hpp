// SPDX-License-Identifier: MIT
// What every study setup carries besides its own members: which study it is,
// the seed of its random streams and the number of worker threads (results
// never depend on it). The file form is io/study_file.hpp's envelope.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "hula/optim/run_log.hpp"
#include "hula/optim/run_report.hpp"

namespace hula::studies {

/// The envelope of a study setup.
struct StudyHeader {
  /// Which study ("match-curvature", "fair-knots", ...).
  std::string kind{};
  /// Seed of the run's random streams. Default 1.
  std::uint64_t seed = 1;
  /// Worker threads (0 = all cores). Results never depend on it. Default 1.
  std::size_t threads = 1;
  /// The run's deadline (`--time`): every optimiser and every re-centred round of the study ends
  /// with its best so far once it passes. Set by the caller, not a file member. Default none.
  optim::Deadline deadline{};
  /// Cancellation token (SIGINT) the optimiser checks between generations, not
  /// owned. Set by the caller, not a file member. Default none.
  const optim::CancellationToken* cancel = nullptr;
  /// Called with each generation of the study's optimiser (progress of a server job). Set by the
  /// caller, not a file member. Default none.
  optim::GenerationCallback on_generation{};
};

/// How a study run went, whatever its kind: the report every door gives beside the study's result.
struct StudyReport {
  /// The study kind ("match-curvature", ...).
  std::string kind{};
  /// True when the cancellation token ended the run: the result is the best so far.
  bool cancelled = false;
  /// Generations of the study's optimiser runs, counted across them (re-centred rounds and the two
  /// fair-knots optimisers each restart at generation 0); 0 for the studies without an optimiser.
  std::size_t generations = 0;
  /// Fitness evaluations of those generations, counted across the runs.
  std::size_t evaluations = 0;
  /// Wall-clock seconds of the run.
  double seconds = 0.0;
};

}  // namespace hula::studies
