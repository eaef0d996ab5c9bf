// SPDX-License-Identifier: MIT
// The document's side of STEP/IGES exchange: curve entities
// out through oli/exchange (the isolated Open CASCADE helper) and the curves
// of a file in as new entities with their names and provenance. Law and
// natural-equation curves leave as their NURBS approximation, with the
// approximation's maximum deviation written into the file's metadata. Only
// built with Open CASCADE (HULA_WITH_OCCT). The lossless path stays JSON
// (json_exchange.hpp).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "hula/oli/document.hpp"
#include "hula/oli/exchange/exchange.hpp"
#include "hula/oli/kernel/kernel.hpp"

namespace hula::oli {

/// The kernel backend the document records (DocumentOptions::backend), from the registry.
/// @throws hula::Error(Errc::InvalidArgument) if this build lacks that backend
[[nodiscard]] std::shared_ptr<const Kernel> document_kernel(const Document& document);

/// The curves of `labels` as export items: each curve's NURBS (a law or natural-equation curve's
/// NURBS approximation with its deviation) under the entity's name.
/// @throws hula::Error(Errc::InvalidArgument) naming a label that is missing or not a curve, or for no labels
[[nodiscard]] std::vector<ExportCurve> export_items(const Document& document, std::span<const Label> labels);

/// Writes the curves of `labels` to a STEP or IGES file (export_items, then export_curves).
/// @throws as export_items and export_curves; the document is only read
[[nodiscard]] ExportReport export_entities(const Document& document, std::span<const Label> labels,
                                           const std::filesystem::path& path, ExchangeFormat format,
                                           const ExchangeOptions& options = {});

/// Adds imported curves as NURBS curve entities named as in the file, with provenance
/// "import:step" or "import:iges" (details: file, source entity, file type). Call inside a
/// transaction, after import_curves has read the file in its helper process.
/// @param format the file's format; by default its extension's (standard input, `-`, has none)
/// @returns the new labels in file order
std::vector<Label> add_imported(Edit& edit, const ImportReport& report, const std::filesystem::path& source,
                                std::optional<ExchangeFormat> format = std::nullopt);

}  // namespace hula::oli
