// SPDX-License-Identifier: MIT
// POST /api/documents/{name}/entities/{label}/study-seed {"study":
// "match-curvature-torsion", "population"?: 40, "generations"?: 40} → the
// study file seeded from the entity's curve (io::seeded_torsion_study_to_json of
// studies::seed_match_setup): its points as the variables, its end
// tangents held, its own κ and τ profiles as the targets — what the
// workbench's "From selection" fills in. Nothing in the document changes.
#include "hula/io/json_read.hpp"
#include "hula/io/match_study_file.hpp"
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

namespace {

namespace json = io::json;

Response study_seed(DocumentRegistry& docs, const Request& request) {
  const Json body = request.json();
  const json::JsonPath root;
  json::reject_unknown_members(body, root, {"study", "population", "generations"});
  const std::string kind = json::get_string(json::require_member(body, root, "study"), json::root_path("study"));
  if (kind != "match-curvature-torsion")
    throw Error(Errc::InvalidArgument,
                "study = \"" + kind + "\": only \"match-curvature-torsion\" is seeded from a curve",
                ErrorWhere{.field = "study"});
  // A first interactive run: a small population over few generations (the page's template sizes).
  studies::TorsionMatchSettings settings{.population = 40, .generations = 40};
  if (const Json* p = json::optional_member(body, "population"))
    settings.population = static_cast<std::size_t>(json::get_integer(*p, json::root_path("population"), 4, 100'000));
  if (const Json* g = json::optional_member(body, "generations"))
    settings.generations =
        static_cast<std::size_t>(json::get_integer(*g, json::root_path("generations"), 0, 1'000'000));
  settings.validate();
  const auto [doc, label] = entity_of(docs, request);
  const oli::Entity e = doc->read([&](const oli::Document& d) { return d.get(label); });
  // Computed outside the lock from the immutable snapshot.
  return json_response(200, io::seeded_torsion_study_to_json(e.curve(), settings));
}

}  // namespace

void add_study_seed(Router& router, const Context& context) {
  DocumentRegistry& docs = context.documents;
  router.add("POST", "/api/documents/{name}/entities/{label}/study-seed",
             [&docs](const Request& request) { return study_seed(docs, request); });
}

}  // namespace hula::server::routes
