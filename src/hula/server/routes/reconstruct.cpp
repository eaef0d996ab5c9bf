// SPDX-License-Identifier: MIT
// POST /api/reconstruct {"kappa", "tau", "length", "start_point"?,
// "start_frame"? {"tangent", "normal"}, "tolerance"?, "fit_tolerance"?, "at"?}
// → {"points": [{"s", "position", "T", "N", "B"}], "curve": the fitted NURBS
// as a curve file, "max_deviation", "integration", "fit"}: the curve with
// curvature κ(s) and torsion τ(s) (intrinsic::reconstruct, thesis 8.2.2), as
// `hula reconstruct` prints it (io::reconstruction_request_json), with its work bounded
// (intrinsic::kFrontEndMaxSteps, kFrontEndMaxSegments) so that a rough law is
// answered with an error naming kappa and the limit, never minutes of work.
//
// POST /api/documents/{name}/entities/{label}/curvature-edit {"kappa", "target"?,
// "tau"?, "hold"?, "max_handles_factor"?, "fit_tolerance"?} → {"revision",
// "changes", "edit"}: design by curvature on the entity's curve
// (oli::edit_curvature, one "edit curvature" undo step; the request and report
// codecs are io/reconstruction_json.hpp): its κ profile replaced or changed,
// its ends, end tangents (and, with "hold": "curvature", end curvatures) kept.
#include <optional>

#include "hula/io/reconstruction_json.hpp"
#include "hula/oli/curvature_edit.hpp"
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

namespace {

Response reconstruct(const Request& request) {
  return json_response(200, io::reconstruction_request_json(request.json()));
}

}  // namespace

void add_reconstruct(Router& router, const Context& context) {
  router.add("POST", "/api/reconstruct", reconstruct);
  DocumentRegistry& docs = context.documents;
  router.add("POST", "/api/documents/{name}/entities/{label}/curvature-edit", [&docs](const Request& request) {
    const io::CurvatureEditRequest edit = io::curvature_edit_request_from_json(request.json());
    const auto [doc, label] = entity_of(docs, request);
    std::optional<studies::CurvatureEditResult> result;
    const Change change = doc->change([&](oli::Document& d) {
      return d.transact("edit curvature",
                        [&](oli::Edit& e) { result = oli::edit_curvature(e, label, edit.edit, edit.options); });
    });
    Json out = change_json(change);  // rethrows the error of a refused edit
    out["edit"] = io::curvature_edit_to_json(*result);
    return json_response(200, out);
  });
}

}  // namespace hula::server::routes
