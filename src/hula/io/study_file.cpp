// SPDX-License-Identifier: MIT
#include "hula/io/study_file.hpp"

#include <limits>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/json_read.hpp"

namespace hula::io {
namespace {

using json::root_path;

constexpr std::string_view kEnvelope[] = {"format", "version", "study", "seed", "threads", "comment"};

}  // namespace

StudyDocument parse_study_json(std::string_view text, std::string_view expected_kind) {
  return study_from_json(json::parse_json_text(text, "study file"), expected_kind);
}

StudyDocument study_from_json(Json body, std::string_view expected_kind) {
  StudyDocument out;
  out.body = std::move(body);
  const Json& doc = out.body;
  if (!doc.is_object()) json::type_error(doc, root_path(""), "a JSON object (a study file)");
  const std::string format = json::get_string(json::require_member(doc, root_path(""), "format"), root_path("format"));
  if (format != "hula-study")
    throw Error(Errc::ParseError,
                "format = " + io::json::quote(format) + ": a study file must have \"format\": \"hula-study\"",
                root_path("format").where);
  (void)json::get_integer(json::require_member(doc, root_path(""), "version"), root_path("version"), 1, 1);
  out.header.kind = json::get_string(json::require_member(doc, root_path(""), "study"), root_path("study"));
  if (out.header.kind != expected_kind)
    throw Error(Errc::ParseError,
                "study = " + io::json::quote(out.header.kind) + ": this command runs \"" + std::string(expected_kind) +
                    "\" studies",
                root_path("study").where);
  if (const Json* s = json::optional_member(doc, "seed"))
    out.header.seed =
        static_cast<std::uint64_t>(json::get_integer(*s, root_path("seed"), 0, std::numeric_limits<long long>::max()));
  if (const Json* t = json::optional_member(doc, "threads"))
    out.header.threads = static_cast<std::size_t>(json::get_integer(*t, root_path("threads"), 0, 1024));
  return out;
}

StudyDocument read_study_file(const std::filesystem::path& path, std::string_view expected_kind) {
  return parse_study_json(io::read_text_file(path), expected_kind);
}

void check_members(const Json& body, std::initializer_list<std::string_view> kind_members) {
  std::vector<std::string_view> allowed(std::begin(kEnvelope), std::end(kEnvelope));
  allowed.insert(allowed.end(), kind_members.begin(), kind_members.end());
  json::reject_unknown_members(body, root_path(""), allowed);
}

Json header_to_json(const studies::StudyHeader& header) {
  Json out = Json::object();
  out["format"] = "hula-study";
  out["version"] = 1;
  out["study"] = header.kind;
  out["seed"] = header.seed;
  out["threads"] = header.threads;
  return out;
}

}  // namespace hula::io
