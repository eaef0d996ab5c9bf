// SPDX-License-Identifier: MIT
// The codec of a target profile (studies::Profile, thesis 8.2): the members
// of a study file that prescribe a curvature or torsion profile,
//   {"law": "0.05 + 0.02*sin(pi*u)", "variable": "u"?}
//   {"samples": [[u, v], ...]}
//   {"csv": "name"}            (two columns u, v; the name goes through the resolver)
//   {"bspline": {"degree", "knots", "coefficients"}}
// (docs/formats.md, "Profiles").
#pragma once

#include "hula/io/json_read.hpp"
#include "hula/io/path_resolver.hpp"
#include "hula/law/expr.hpp"
#include "hula/studies/profile.hpp"

namespace hula::io {

using json::Json;

/// Reads a profile member of a study file.
/// @param value the JSON value; @param path its path for messages (e.g. `target`)
/// @param resolver decides which file a "csv" name opens (relative_to the study's folder on the
///   command line, confined_to a workspace in a server)
/// @param context the law context for a "law" form
/// @throws hula::Error(Errc::ParseError) naming the path for an unknown form or member,
///   a law the parser refuses, a CSV that is not two columns
/// @throws hula::Error(Errc::NonFiniteInput) for NaN or infinite samples (CSV "nan" included)
/// @throws hula::Error(Errc::IoError) if the CSV cannot be read; the resolver's errors for a name
///   it refuses
[[nodiscard]] studies::Profile profile_from_json(const Json& value, const json::JsonPath& path,
                                                 const PathResolver& resolver, const law::Context& context);

}  // namespace hula::io
