// SPDX-License-Identifier: MIT
// The counts an IGES file states before its arrays, checked against what the
// file holds. Open CASCADE's IGES reader allocates (and fills) the arrays of an
// entity from the counts in its parameter data before reading them: a rational
// B-spline curve (126) stating K = 150,000,000 made the exchange helper use
// 3.5 GB for 32 s and crash. Before the helper runs, every such count is bounded
// by the parameters the entity holds: a curve (126) needs K + M + 2 knots and
// K + 1 weights and control points, a surface (128) the same in two directions,
// a composite curve (102) N pointers, copious data (106) N points, a
// parametric spline (112) N segments, a parametric spline surface (114) M and
// N patches. The file is read line by line (nothing proportional to it is held).
#pragma once

#include <filesystem>
#include <istream>
#include <string_view>

namespace hula::io {

/// Checks the counts of an IGES file's entities (see above).
/// @param name the file's name, as the error names it
/// @throws hula::Error(Errc::ParseError) naming the file, the entity (its directory entry and type) and the
///   count that exceeds the parameters it holds
void check_iges_counts(std::istream& in, std::string_view name);

/// check_iges_counts of a file (nothing when it cannot be opened: the reader reports that).
/// @throws hula::Error(Errc::ParseError) as check_iges_counts
void check_iges_file_counts(const std::filesystem::path& path);

}  // namespace hula::io
