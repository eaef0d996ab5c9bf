// SPDX-License-Identifier: MIT
// POST /api/reconstruct {"kappa", "tau", "length", "start_point"?,
// "start_frame"? {"tangent", "normal"}, "tolerance"?, "fit_tolerance"?, "at"?}
// → {"points": [{"s", "position", "T", "N", "B"}], "curve": the fitted NURBS
// as a curve file, "max_deviation", "integration", "fit"}: the curve with
// curvature κ(s) and torsion τ(s) (intrinsic::reconstruct, thesis 8.2.2), as
// `hula reconstruct` prints it (io::reconstruction_request_json), with its work bounded
// (intrinsic::kFrontEndMaxSteps, kFrontEndMaxSegments) so that a rough law is
// answered with an error naming kappa and the limit, never minutes of work.
#include "hula/io/reconstruction_json.hpp"
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

namespace {

Response reconstruct(const Request& request) {
  return json_response(200, io::reconstruction_request_json(request.json()));
}

}  // namespace

void add_reconstruct(Router& router, const Context&) { router.add("POST", "/api/reconstruct", reconstruct); }

}  // namespace hula::server::routes
