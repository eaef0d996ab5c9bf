// SPDX-License-Identifier: MIT
// The codec of the common envelope of study files (docs/formats.md "Study files"): one JSON
// document holds the whole setup of a curve-optimisation study (curve,
// target, variables and bounds, algorithm and settings) so that a run can be
// repeated exactly. Every study file has
//
//   {"format": "hula-study", "version": 1, "study": "<kind>",
//    "seed": <unsigned, default 1>, "threads": <unsigned, default 1>, ...}
//
// and the members its kind defines. Each kind's reader lists its members and
// calls check_members, so that a misspelt field is an error, never ignored;
// all checks happen before any run starts.
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

#include "hula/io/json_read.hpp"
#include "hula/studies/study.hpp"

namespace hula::io {

/// The JSON value type of the io module.
using Json = nlohmann::ordered_json;

/// A parsed study document and its header.
struct StudyDocument {
  studies::StudyHeader header{};
  Json body{};
};

/// Parses study JSON text and checks the envelope.
/// @param text the file's contents
/// @param expected_kind the study kind the caller runs ("match-curvature", ...)
/// @throws hula::Error(Errc::ParseError) for JSON syntax (line, column), a
///   missing or wrong "format"/"version", or a "study" other than expected_kind
/// @throws hula::Error(Errc::ParseError) for a seed or threads that is not a non-negative integer
[[nodiscard]] StudyDocument parse_study_json(std::string_view text, std::string_view expected_kind);

/// The same from a JSON value (a study a document stores, a request body): no text in between.
/// @throws as parse_study_json, but for JSON syntax
[[nodiscard]] StudyDocument study_from_json(Json body, std::string_view expected_kind);

/// Reads a study file.
/// @throws hula::Error(Errc::IoError) if it cannot be read; otherwise as parse_study_json
[[nodiscard]] StudyDocument read_study_file(const std::filesystem::path& path, std::string_view expected_kind);

/// Refuses members of the study document outside `kind_members` and the
/// envelope's own (format, version, study, seed, threads, comment).
/// @throws hula::Error(Errc::ParseError) naming the unknown member and the expected ones
void check_members(const Json& body, std::initializer_list<std::string_view> kind_members);

/// The envelope as JSON, to which a kind adds its members when it writes the
/// resolved setup of a run (so the run can be repeated exactly).
[[nodiscard]] Json header_to_json(const studies::StudyHeader& header);

}  // namespace hula::io
