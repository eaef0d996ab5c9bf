// SPDX-License-Identifier: MIT
// The routes of the HTTP API, one file per resource (docs/server.md lists
// them; the OpenAPI document, openapi.json, is their contract). A route reads
// the request's JSON with the io readers, calls the module that does the
// work and encodes the result; it holds no logic of its own.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include "hula/oli/document.hpp"
#include "hula/server/documents.hpp"
#include "hula/server/jobs.hpp"
#include "hula/server/router.hpp"

namespace hula::server::routes {

/// What the routes share.
struct Context {
  std::string version;
  std::filesystem::path workspace;
  JobPool& jobs;
  DocumentRegistry& documents;
};

/// GET /api/health.
void add_health(Router& router, const Context& context);
/// GET /api/openapi.json.
void add_openapi(Router& router, const Context& context);
/// POST /api/law.
void add_law(Router& router, const Context& context);
/// POST /api/reconstruct, POST /api/documents/{name}/entities/{label}/curvature-edit.
void add_reconstruct(Router& router, const Context& context);
/// POST /api/intersect, POST /api/distance.
void add_intersect(Router& router, const Context& context);
/// POST /api/offset, /api/helical-offset, /api/orthotomic, /api/polar.
void add_constructions(Router& router, const Context& context);
/// POST /api/match, /api/blend (two curves joined: io::match_answer, io::blend_answer).
void add_joins(Router& router, const Context& context);
/// POST /api/clothoid (clothoid and biarc interpolation, through two points or N).
void add_clothoid(Router& router, const Context& context);
/// POST /api/rebuild, /api/reduce-degree, /api/interpolate-closed, /api/hermite-frenet.
void add_curve_edits(Router& router, const Context& context);
/// The curve file under `field` of a request body, errors naming it ("a.control_points[2]: ...").
[[nodiscard]] curve::Curve read_curve_member(const Json& body, const char* field);
/// POST /api/jobs, GET /api/jobs/{id}, GET /api/jobs/{id}/events, DELETE /api/jobs/{id}.
void add_jobs(Router& router, const Context& context);

/// GET|POST /api/documents, GET|DELETE /api/documents/{name}, undo, redo, history, events.
void add_documents(Router& router, const Context& context);
/// POST /api/documents/{name}/entities, GET|PUT|PATCH|DELETE .../entities/{label}, .../analysis,
/// .../insert-knot, .../elevate.
void add_entities(Router& router, const Context& context);

/// The label of an entity route ({label}), refusing anything but a positive integer (400 InvalidArgument).
[[nodiscard]] oli::Label parse_label(const std::string& text);
/// The document and the label of an entity route (/api/documents/{name}/entities/{label}...), 404 when the
/// document has no such entity.
[[nodiscard]] std::pair<std::shared_ptr<OpenDocument>, oli::Label> entity_of(DocumentRegistry& docs,
                                                                             const Request& request);

/// POST /api/documents/{name}/entities/{label}/study-seed (a study file seeded from the entity's curve).
void add_study_seed(Router& router, const Context& context);

/// {"revision", "changes"} of a committed change, the change set with "entities": the entities it added
/// or changed as GET .../entities/{label} gives them; a rolled-back change rethrows its error.
[[nodiscard]] Json change_json(const Change& change);
/// change_json as a response with `status`.
[[nodiscard]] Response change_response(const Change& change, unsigned status);

/// The OpenAPI 3.1 document (openapi.json, embedded at build time).
[[nodiscard]] const std::string& openapi_text();

}  // namespace hula::server::routes
