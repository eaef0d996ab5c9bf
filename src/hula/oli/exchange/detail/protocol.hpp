// SPDX-License-Identifier: MIT
// The JSON messages between the caller and the hula-exchange helper process.
// Request file:  {"operation": "export", "format": "step-ap214", "path": P,
//                 "curves": [{"name": N, "deviation": d, "curve": CURVE}]}
//             |  {"operation": "import", "path": P}
// Answer file:   {"ok": {"curves": n, "max_deviation": d}}                     (export)
//             |  {"ok": {"curves": [{"name", "source", "type", "curve": CURVE}],
//                        "skipped": n, "warnings": [...]}}                       (import)
//             |  {"error": {"code", "message", "where"}}                        (io/error_json.hpp)
// CURVE is the curve-file document of the one curve value type (curve::Curve, io/json_curve.hpp),
// here always of kind "nurbs": a law or natural-equation curve crosses as its NURBS stand-in with
// its deviation, so the helper never re-fits it (bit-exact doubles).
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "hula/io/json_curve.hpp"
#include "hula/oli/exchange/exchange.hpp"

namespace hula::oli::detail {

/// The helper's exit status when memory ran out (std::bad_alloc): it writes no answer, and the caller
/// reports ExchangeOutOfMemory.
inline constexpr int kHelperOutOfMemoryStatus = 6;

/// An export request as the helper sees it.
struct ExportRequest {
  ExchangeFormat format{};
  std::filesystem::path path;
  std::vector<ExportCurve> curves;
};

/// An import request as the helper sees it.
struct ImportRequest {
  std::filesystem::path path;
};

using Request = std::variant<ExportRequest, ImportRequest>;

[[nodiscard]] io::Json request_to_json(const Request& request);
/// @throws hula::Error(Errc::ParseError) naming the member at fault
[[nodiscard]] Request request_from_json(const io::Json& document);

[[nodiscard]] io::Json export_answer_to_json(const ExportReport& report);
[[nodiscard]] io::Json import_answer_to_json(const ImportReport& report);
/// The "ok" member of an answer; throws the answer's error as hula::Error if it is an error answer.
/// @throws hula::Error with the code, message and where of an error answer
/// @throws hula::Error(Errc::HelperFailure) if the document is neither form
[[nodiscard]] const io::Json& answer_ok(const io::Json& document);
/// @throws as answer_ok, or hula::Error(Errc::HelperFailure) for a malformed answer
[[nodiscard]] ImportReport import_answer_from_json(const io::Json& ok);

}  // namespace hula::oli::detail
