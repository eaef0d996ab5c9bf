// SPDX-License-Identifier: MIT
// JSON export and import of entities: the lossless exchange path.
// One entity is written in its own file format — a curve as its curve
// file, a point set as a points file, a study as its study file — so any
// `hula` command reads it; several entities as a "hula-document" JSON file
// (docs/formats.md "Document JSON"). Import reads any of these and adds new
// entities (new labels) with provenance "import:json".
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hula/oli/document.hpp"

namespace hula::oli {

/// The "version" of the hula-document JSON this build writes and the highest it reads.
inline constexpr int kDocumentJsonVersion = 1;

/// The kind shown to users: the curve's kind name ("nurbs", "bezier", "interpolated",
/// "hermite", "law", "natural"), "point-set" or "study".
[[nodiscard]] std::string entity_display_kind(const Entity& entity);

/// The JSON to write for `labels`: one entity in its own format, several as a hula-document.
/// @throws hula::Error(Errc::InvalidArgument) naming a label that is not in the document, or for no labels
[[nodiscard]] Json export_json(const Document& document, std::span<const Label> labels);

/// Adds the entities of `input` (a curve file, a points array, or a hula-document) inside a
/// transaction; returns their new labels in file order.
/// @param source the file name recorded in the provenance
/// @throws hula::Error(Errc::ParseError) naming the member for anything else, and for a
///   hula-document whose "version" is not 1..kDocumentJsonVersion or that has a member other than
///   "format", "version" and "entities" (field "version" / the member); the codecs' errors
std::vector<Label> import_json(Edit& edit, const Json& input, std::string_view source);

/// Adds a point set read from a point file (io::parse_points: text columns, airfoil files, JSON) inside
/// a transaction, with the provenance "import:points" naming `source`; returns its label.
Label import_points(Edit& edit, PointSet points, std::string_view source);

}  // namespace hula::oli
