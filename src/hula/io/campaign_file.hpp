// SPDX-License-Identifier: MIT
// Campaign files and their results files (docs/formats.md "Campaign files"):
// the items of a campaign (study files, or one study's seeds × settings), the
// study file an item runs (its seed and settings merged in), the record of a
// finished item and the results file `hula batch` rewrites after each item
// (so an interrupted campaign resumes). Running the items is the caller's.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/io/json_curve.hpp"

namespace hula::io {

/// One unit of work of a campaign.
struct CampaignItem {
  std::string id;
  std::filesystem::path study;        ///< the study file, relative paths resolved against the campaign's folder
  std::optional<std::uint64_t> seed;  ///< replaces the study's seed
  Json set;                           ///< JSON merge patch applied to the study (null = none)
};

/// The items of a campaign file {"format": "hula-campaign", "version": 1, "comment"?, "items"?: [{"study", "id"?,
/// "seed"?, "set"?}], "sweep"?: {"study", "seeds"?, "settings"?}}, in file order: "items" first, then the sweep's
/// settings × seeds (ids "<stem>/settings<j>/seed<s>").
/// @throws hula::Error(Errc::ParseError) naming the member for a malformed file; Errc::InvalidOption for a
///   repeated id, a bad seed or no items
[[nodiscard]] std::vector<CampaignItem> read_campaign_file(const std::filesystem::path& path);

/// The study document an item runs: its study file with the item's seed and settings merged in.
/// @throws hula::Error(Errc::ParseError) for a file that is not a study file (no "study" kind)
[[nodiscard]] Json campaign_item_study(const CampaignItem& item);

/// The record of a finished item: {"id", "study", "seed", "rank", "seconds", "exit", "status": "ok" | "failed",
/// "result" (its stdout as JSON, or as text when it is not JSON) | "error" (its stderr likewise, or "terminated
/// by signal N" when empty)}; `exit` is 128 + N for a signal.
[[nodiscard]] Json campaign_item_record(const CampaignItem& item, int rank, double seconds, int exit,
                                        const std::string& out, const std::string& err);

/// The record of an item that could not start (an unreadable or malformed study file).
[[nodiscard]] Json campaign_failed_record(const CampaignItem& item, const Error& error, int rank, int exit);

/// The records of a results file's finished items by id ("ok" ones only: failed items run again); none when
/// the file does not exist.
/// @throws hula::Error(Errc::ParseError) for a file that is not JSON
[[nodiscard]] std::map<std::string, Json> read_campaign_results(const std::filesystem::path& path);

/// The results file's text {"format": "hula-campaign-results", "version": 1, "campaign", "items": {id: record}}
/// with the records of `done` in the campaign's item order.
[[nodiscard]] std::string campaign_results_text(const std::string& campaign, const std::vector<CampaignItem>& items,
                                                const std::map<std::string, Json>& done);

}  // namespace hula::io
