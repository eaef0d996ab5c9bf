// SPDX-License-Identifier: MIT
// The study file of kind "fit" (docs/formats.md "fit study"): scanned points to a
// class-A curve (studies::fit_scan). The reader checks every member before any
// work; the result codec writes the figures before and after fairing, the strays
// by index and the resolved setup, so that a run can be repeated exactly.
#pragma once

#include <string>
#include <vector>

#include "hula/io/path_resolver.hpp"
#include "hula/io/study_file.hpp"
#include "hula/studies/scan_fit.hpp"

namespace hula::io {

/// A "fit" study.
struct FitStudy {
  studies::StudyHeader header{};
  /// "points": an inline array of [x, y] / [x, y, z] points, or the name of a points file (CSV or
  /// JSON, resolved by the caller's PathResolver).
  std::vector<Vec3> points;
  /// The points file name as written, empty for inline points.
  std::string points_file{};
  /// "class" ("A" → 0.3, "B" → 0.5) or "tolerance" (> 0), "degree", "min_degree", "ordered", "fair".
  studies::ScanFitOptions options{};
};

/// Reads a "fit" study body.
/// @throws hula::Error(Errc::ParseError) naming an unknown or missing member, a bad value, or both
///   "class" and "tolerance"; the points file's errors (ParseError with line/column, IoError naming
///   the path); hula::Error(Errc::InvalidOption) naming the option out of range
[[nodiscard]] FitStudy fit_study_from_json(const StudyDocument& document, const PathResolver& resolver);

/// The resolved setup (points inline or by file name, tolerance, degrees, ordered, fair) as a study document.
[[nodiscard]] Json fit_study_to_json(const FitStudy& study);

/// The result: tolerance, strays (indices), noise scale, smoothing, fits, and for "before" (the
/// tolerance fit) and "after" (the faired curve) the max/mean deviation, control points, inflections,
/// curvature extrema, ∫κ'² ds and ∫κ² ds.
[[nodiscard]] Json fit_result_to_json(const studies::ScanFitResult& result, const studies::ScanFitOptions& options);

}  // namespace hula::io
