// SPDX-License-Identifier: MIT
#include "hula/oli/exchange/detail/protocol.hpp"

#include <string>

#include "hula/core/error.hpp"
#include "hula/io/error_json.hpp"
#include "hula/io/json_read.hpp"

namespace hula::oli::detail {
namespace {

// The Errc whose stable name is `name` (errc_name's inverse), or nullopt.
std::optional<Errc> errc_from_name(std::string_view name) {
  for (int i = 0; i <= static_cast<int>(kLastErrc); ++i) {
    const auto code = static_cast<Errc>(i);
    if (errc_name(code) == name) return code;
  }
  return std::nullopt;
}

[[noreturn]] void malformed(const std::string& what) {
  throw Error(Errc::HelperFailure, "the exchange helper's answer is malformed: " + what, {.field = "answer"});
}

}  // namespace

io::Json request_to_json(const Request& request) {
  io::Json out = io::Json::object();
  if (const auto* e = std::get_if<ExportRequest>(&request)) {
    out["operation"] = "export";
    out["format"] = std::string(exchange_format_name(e->format));
    out["path"] = e->path.string();
    io::Json curves = io::Json::array();
    for (const auto& c : e->curves)
      curves.push_back({{"name", c.name},
                        {"deviation", c.deviation},
                        {"colour", c.colour},
                        {"layer", c.layer},
                        {"curve", io::curve_to_json(curve::Curve(c.curve))}});
    out["curves"] = std::move(curves);
  } else {
    out["operation"] = "import";
    out["path"] = std::get<ImportRequest>(request).path.string();
  }
  return out;
}

Request request_from_json(const io::Json& document) {
  namespace js = io::json;
  const auto root = js::root_path("");
  if (!document.is_object()) throw Error(Errc::ParseError, "the request is not a JSON object", {.field = "request"});
  const std::string operation =
      js::get_string(js::require_member(document, root, "operation"), root.member("operation"));
  const std::filesystem::path path = js::get_string(js::require_member(document, root, "path"), root.member("path"));
  if (operation == "import") return ImportRequest{path};
  if (operation != "export")
    throw Error(Errc::ParseError, "unknown operation '" + operation + "' (export | import)", {.field = "operation"});
  ExportRequest r;
  r.path = path;
  r.format =
      exchange_format_from_name(js::get_string(js::require_member(document, root, "format"), root.member("format")));
  const auto& curves = js::get_array(js::require_member(document, root, "curves"), root.member("curves"));
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const auto p = root.member("curves").element(i);
    auto optional_string = [&](const char* member) {
      const auto* v = js::optional_member(curves[i], member);
      return v == nullptr ? std::string() : js::get_string(*v, p.member(member));
    };
    r.curves.push_back({js::get_string(js::require_member(curves[i], p, "name"), p.member("name")),
                        io::curve_from_json(js::require_member(curves[i], p, "curve")).nurbs(),
                        js::get_number(js::require_member(curves[i], p, "deviation"), p.member("deviation")),
                        optional_string("colour"), optional_string("layer")});
  }
  return r;
}

io::Json export_answer_to_json(const ExportReport& report) {
  return {{"ok", {{"curves", report.curves}, {"max_deviation", report.max_deviation}}}};
}

io::Json import_answer_to_json(const ImportReport& report) {
  io::Json curves = io::Json::array();
  for (const auto& c : report.curves)
    curves.push_back({{"name", c.name},
                      {"source", c.source},
                      {"type", c.type},
                      {"colour", c.colour},
                      {"layer", c.layer},
                      {"curve", io::curve_to_json(curve::Curve(c.curve))}});
  return {{"ok", {{"curves", std::move(curves)}, {"skipped", report.skipped}, {"warnings", report.warnings}}}};
}

const io::Json& answer_ok(const io::Json& document) {
  namespace js = io::json;
  if (!document.is_object()) malformed("not a JSON object");
  if (const auto* ok = js::optional_member(document, "ok")) return *ok;
  const auto* error = js::optional_member(document, "error");
  if (error == nullptr || !error->is_object()) malformed("neither \"ok\" nor \"error\"");
  const auto* code = js::optional_member(*error, "code");
  const auto* message = js::optional_member(*error, "message");
  if (code == nullptr || !code->is_string() || message == nullptr || !message->is_string())
    malformed("an error without code and message");
  const auto errc = errc_from_name(code->get<std::string>());
  if (!errc) malformed("unknown error code '" + code->get<std::string>() + "'");
  ErrorWhere where;
  if (const auto* w = js::optional_member(*error, "where"); w != nullptr && w->is_object()) {
    auto index = [&](const char* name) -> std::optional<std::size_t> {
      const auto* v = js::optional_member(*w, name);
      if (v == nullptr || !v->is_number_unsigned()) return std::nullopt;
      return v->get<std::size_t>();
    };
    if (const auto* f = js::optional_member(*w, "field"); f != nullptr && f->is_string())
      where.field = f->get<std::string>();
    where.index = index("index");
    where.component = index("component");
    where.line = index("line");
    where.column = index("column");
  }
  throw Error(*errc, message->get<std::string>(), where);
}

ImportReport import_answer_from_json(const io::Json& ok) {
  try {
    ImportReport report;
    for (const auto& c : ok.at("curves"))
      report.curves.push_back({c.at("name").get<std::string>(), c.at("source").get<std::string>(),
                               c.at("type").get<std::string>(), io::curve_from_json(c.at("curve")).nurbs(),
                               c.value("colour", std::string()), c.value("layer", std::string())});
    report.skipped = ok.at("skipped").get<std::size_t>();
    report.warnings = ok.at("warnings").get<std::vector<std::string>>();
    return report;
  } catch (const nlohmann::json::exception& e) {
    malformed(e.what());
  }
}

}  // namespace hula::oli::detail
