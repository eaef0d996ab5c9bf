// SPDX-License-Identifier: MIT
// POST /api/clothoid {"points"?, "closed"?, "fit"?, "start_point"?, "start_angle"?, "end_point"?,
// "end_angle"?, "start_curvature"?, "end_curvature"?, "at"?} → io::clothoid_answer (`hula clothoid`):
// the G1 / G2 clothoid Hermite interpolants, the biarc, or a G1 / G2 clothoid or biarc spline through
// points (open or closed), with the curve as a curve file under "curve" (a natural curve held by its
// curvature law; the command writes it to -o instead). The request codec is
// io::clothoid_request_from_json.
#include "hula/io/exact_curves.hpp"
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

void add_clothoid(Router& router, const Context& /*context*/) {
  router.add("POST", "/api/clothoid", [](const Request& request) {
    io::ClothoidAnswer answer = io::clothoid_answer(io::clothoid_request_from_json(request.json()));
    Json out = std::move(answer.json);
    out["curve"] = io::curve_to_json(io::clothoid_curve(answer.segments, curve::kNaturalTolerance));
    return json_response(200, out);
  });
}

}  // namespace hula::server::routes
