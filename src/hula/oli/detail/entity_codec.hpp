// SPDX-License-Identifier: MIT
// Encoding of entity states for the store (docs/formats.md "Entity state"):
//
//   bytes 0-3  "HLE2"  magic and codec version 2 ("HLE1", version 1, is still read)
//   u32 LE     n: length of the skeleton
//   n bytes    the skeleton: the entity as JSON (entity_state_to_json) in which
//              every array of floating-point numbers, and every array of
//              equal-length arrays of floating-point numbers (points), inside
//              "data" is replaced by {"$f64": i} or {"$f64": i, "$cols": k}
//   u32 LE     m: the number of packed arrays
//   m times    u64 LE count, then count little-endian IEEE-754 doubles
//
//              and every study run's log by {"$log": i}: packed array i holds
//              the log as columns (per generation a header of five counts,
//              then variables, objectives, violations, fitnesses, failed flags)
//
// Large numeric arrays (control points, knots, run logs) are thus stored
// compactly and bit-exactly instead of as decimal text; the skeleton keeps the
// document's own JSON formats for everything else. A run log is written from
// the shared optim::RunLog straight into its one array (no JSON tree per
// individual, which cost about as much as the run). Version 1 differs only in
// writing run logs as their JSON (io::run_log_to_json) inside the skeleton.
#pragma once

#include <string>
#include <string_view>

#include "hula/oli/detail/entity_state.hpp"

namespace hula::oli::detail {

/// The entity's own data as JSON: a curve as its curve file, a point set as a
/// points array (with "dimension"), a study as {"setup", "runs"}.
[[nodiscard]] Json entity_data_to_json(const EntityState& state);
/// The whole state as JSON: {"kind", "attributes", "provenance", "constraints", "data"}.
[[nodiscard]] Json entity_state_to_json(const EntityState& state);
/// Rebuilds a state from entity_state_to_json's form (validating the data: a curve is rebuilt
/// through its codec, so an invalid curve cannot load).
/// @throws hula::Error(Errc::ParseError) naming the member; the curve codec's errors
[[nodiscard]] StatePtr entity_state_from_json(const Json& json);
/// Rebuilds one kind's data from entity_data_to_json's form into `state`.
void entity_data_from_json(EntityKind kind, const Json& data, EntityState& state);

/// Encodes a state as the store keeps it.
[[nodiscard]] std::string encode_state(const EntityState& state);
/// Decodes encode_state's bytes.
/// @throws hula::Error(Errc::ParseError) for a wrong magic, a truncated blob, bad skeleton
///   JSON or an array reference out of range; the data's own errors
[[nodiscard]] StatePtr decode_state(std::string_view bytes);

/// Checks that every double of a point set is finite.
/// @throws hula::Error(Errc::NonFiniteInput) naming "points" and the index
void validate_point_set(const PointSet& points);

}  // namespace hula::oli::detail
