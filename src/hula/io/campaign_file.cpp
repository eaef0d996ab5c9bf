// SPDX-License-Identifier: MIT
// Campaign files and their results (campaign_file.hpp).
#include "hula/io/campaign_file.hpp"

#include "hula/io/atomic_file.hpp"

namespace hula::io {

namespace {

namespace fs = std::filesystem;

Json parse_json_file(const fs::path& path, const std::string& field) {
  const std::string text = io::read_text_file(path);
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& e) {
    throw Error(Errc::ParseError, path.string() + ": " + e.what(), {.field = field});
  }
}

// A string member, or `fallback` when it is absent or not a string. (Json::value() trips GCC 12's
// -Wnull-dereference inside nlohmann's inlined code.)
std::string string_member(const Json& j, const char* key, const std::string& fallback) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get_ref<const std::string&>() : fallback;
}

std::uint64_t as_seed(const Json& v, const std::string& field) {
  if (!v.is_number_unsigned())
    throw Error(Errc::InvalidOption, field + " must be a non-negative integer seed", {.field = field});
  return v.get<std::uint64_t>();
}

// The campaign's items, in file order: "items" first, then the sweep's seeds x settings.
}  // namespace

std::vector<CampaignItem> read_campaign_file(const fs::path& path) {
  const Json doc = parse_json_file(path, "campaign");
  if (!doc.is_object() || string_member(doc, "format", "") != "hula-campaign" || !doc.contains("version") ||
      doc["version"] != 1) {
    throw Error(Errc::ParseError, path.string() + ": not a campaign file (format \"hula-campaign\", version 1)",
                {.field = "format"});
  }
  for (const auto& [key, value] : doc.items()) {
    if (key != "format" && key != "version" && key != "comment" && key != "items" && key != "sweep")
      throw Error(Errc::ParseError, "unknown member \"" + key + "\" of the campaign", {.field = key});
  }
  const fs::path base = path.parent_path();
  std::vector<CampaignItem> items;
  if (doc.contains("items")) {
    const Json& list = doc["items"];
    if (!list.is_array()) throw Error(Errc::ParseError, "items must be an array", {.field = "items"});
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Json& j = list[i];
      const std::string field = "items[" + std::to_string(i) + "]";
      if (!j.is_object() || !j.contains("study") || !j["study"].is_string())
        throw Error(Errc::ParseError, field + " needs a \"study\" file name", {.field = field, .index = i});
      CampaignItem item;
      item.study = base / j["study"].get_ref<const std::string&>();
      item.id = string_member(j, "id", item.study.stem().string());
      if (j.contains("seed")) item.seed = as_seed(j["seed"], field + ".seed");
      if (j.contains("set")) item.set = j["set"];
      items.push_back(std::move(item));
    }
  }
  if (doc.contains("sweep")) {
    const Json& s = doc["sweep"];
    if (!s.is_object() || !s.contains("study") || !s["study"].is_string())
      throw Error(Errc::ParseError, "sweep needs a \"study\" file name", {.field = "sweep.study"});
    const fs::path study = base / s["study"].get_ref<const std::string&>();
    std::vector<std::optional<std::uint64_t>> seeds{std::nullopt};
    if (s.contains("seeds")) {
      seeds.clear();
      for (const Json& v : s["seeds"]) seeds.emplace_back(as_seed(v, "sweep.seeds"));
    }
    std::vector<Json> sets{Json()};
    if (s.contains("settings")) {
      sets.clear();
      for (const Json& v : s["settings"]) sets.push_back(v);
    }
    for (std::size_t j = 0; j < sets.size(); ++j)
      for (const auto& seed : seeds) {
        CampaignItem item{study.stem().string(), study, seed, sets[j]};
        if (sets.size() > 1) item.id += "/settings" + std::to_string(j);
        if (seed) item.id += "/seed" + std::to_string(*seed);
        items.push_back(std::move(item));
      }
  }
  std::map<std::string, std::size_t> seen;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (auto [it, fresh] = seen.emplace(items[i].id, i); !fresh)
      throw Error(Errc::InvalidOption,
                  "item id \"" + items[i].id + "\" appears twice (items " + std::to_string(it->second) + " and " +
                      std::to_string(i) + ")",
                  {.field = "id", .index = i});
  }
  if (items.empty()) throw Error(Errc::InvalidOption, "the campaign has no items", {.field = "items"});
  return items;
}

Json campaign_item_study(const CampaignItem& item) {
  Json study = parse_json_file(item.study, "study");
  if (!study.is_object() || !study.contains("study") || !study["study"].is_string())
    throw Error(Errc::ParseError, item.study.string() + ": not a study file (no \"study\" kind)", {.field = "study"});
  if (item.seed) study["seed"] = *item.seed;
  if (!item.set.is_null()) study.merge_patch(item.set);
  return study;
}

Json campaign_item_record(const CampaignItem& item, int rank, double seconds, int exit, const std::string& out,
                          const std::string& err) {
  Json j = Json::object();
  j["id"] = item.id;
  j["study"] = item.study.string();
  j["seed"] = item.seed ? Json(*item.seed) : Json(nullptr);
  j["rank"] = rank;
  j["seconds"] = seconds;
  j["exit"] = exit;
  j["status"] = exit == 0 ? "ok" : "failed";
  const auto parsed = [](const std::string& text) {
    try {
      return Json::parse(text);
    } catch (const Json::parse_error&) {
      return Json(text);
    }
  };
  if (exit == 0)
    j["result"] = parsed(out);
  else
    j["error"] = err.empty() ? Json("terminated by signal " + std::to_string(exit - 128)) : parsed(err);
  return j;
}

Json campaign_failed_record(const CampaignItem& item, const Error& e, int rank, int exit) {
  return Json{{"id", item.id},
              {"study", item.study.string()},
              {"seed", item.seed ? Json(*item.seed) : Json(nullptr)},
              {"rank", rank},
              {"seconds", 0.0},
              {"exit", exit},
              {"status", "failed"},
              {"error", Json{{"code", errc_name(e.code())}, {"message", e.message()}}}};
}

std::map<std::string, Json> read_campaign_results(const fs::path& path) {
  std::map<std::string, Json> done;
  if (!fs::exists(path)) return done;
  const Json old = parse_json_file(path, "results");
  if (old.contains("items") && old["items"].is_object())
    for (const auto& [id, value] : old["items"].items())
      if (string_member(value, "status", "") == "ok") done[id] = value;  // failed items run again
  return done;
}

std::string campaign_results_text(const std::string& campaign, const std::vector<CampaignItem>& items,
                                  const std::map<std::string, Json>& done) {
  Json list = Json::object();
  for (const CampaignItem& i : items)
    if (auto it = done.find(i.id); it != done.end()) list[i.id] = it->second;
  return Json{{"format", "hula-campaign-results"}, {"version", 1}, {"campaign", campaign}, {"items", std::move(list)}}
             .dump(1) +
         "\n";
}

}  // namespace hula::io
