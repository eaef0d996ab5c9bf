// SPDX-License-Identifier: MIT
// Problem files (see problem_file.hpp and docs/formats.md "Problem files").
#include "hula/io/problem_file.hpp"

#include <set>
#include <string>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/json_read.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/tape.hpp"

namespace hula::io {

namespace {

using json::Json;
using json::JsonPath;
using json::root_path;

optim::Variable read_variable(const Json& value, const JsonPath& path, law::Context& context,
                              std::set<std::string>& names) {
  if (!value.is_object()) json::type_error(value, path, "an object {\"name\", \"lower\", \"upper\"}");
  optim::Variable v;
  const JsonPath name_path = path.member("name");
  v.name = json::get_string(json::require_member(value, path, "name"), name_path);
  try {
    (void)context.parameter(v.name);  // refuses non-identifiers, function names, pi and e
  } catch (const Error& e) {
    throw Error(Errc::ParseError,
                name_path.text + " = " + json::quote(v.name) + " cannot name a variable: " + e.message(),
                name_path.where);
  }
  if (!names.insert(v.name).second)
    throw Error(Errc::ParseError, name_path.text + " = " + json::quote(v.name) + " repeats an earlier variable name",
                name_path.where);
  v.lower = json::get_number(json::require_member(value, path, "lower"), path.member("lower"));
  v.upper = json::get_number(json::require_member(value, path, "upper"), path.member("upper"));
  if (const Json* p = json::optional_member(value, "precision"))
    v.precision = json::get_number(*p, path.member("precision"));
  return v;
}

// Parses one scalar expression; errors start with the member's path and keep
// the parser's line and column inside the expression string.
law::Law read_expression(const std::string& text, const JsonPath& path, const law::Context& context,
                         const law::ParseOptions& options) {
  law::Law law;
  try {
    law = law::parse(text, context, options);
  } catch (const Error& e) {
    ErrorWhere where = path.where;
    where.line = e.where().line;
    where.column = e.where().column;
    throw Error(Errc::ParseError, path.text + ": " + e.message(), where);
  }
  if (law.dimension() != 1)
    throw Error(Errc::ParseError,
                path.text + ": \"" + text + "\" is a " + std::to_string(law.dimension()) +
                    "-vector; objectives and constraints must be scalars",
                path.where);
  return law;
}

}  // namespace

ProblemFile parse_problem_json(std::string_view text) {
  return problem_from_json(json::parse_json_text(text, "problem file"));
}

ProblemFile problem_from_json(const Json& doc) {
  const JsonPath root;
  if (!doc.is_object()) json::type_error(doc, root_path(""), "an object (a problem file)");

  ProblemFile out;
  optim::Problem& problem = out.problem;
  problem.name = "problem-file";
  if (const Json* n = json::optional_member(doc, "name")) problem.name = json::get_string(*n, root_path("name"));

  law::Context context;
  law::ParseOptions options;
  options.parameters.clear();
  std::set<std::string> names;
  const Json& vars = json::get_array(json::require_member(doc, root, "variables"), root_path("variables"));
  if (vars.empty())
    throw Error(Errc::ParseError, "variables is empty: a problem needs at least one variable", {.field = "variables"});
  for (std::size_t i = 0; i < vars.size(); ++i) {
    problem.variables.push_back(read_variable(vars[i], root_path("variables").element(i), context, names));
    options.parameters.push_back(problem.variables.back().name);
  }

  // Tape outputs in the order Problem::evaluate writes them: objectives,
  // inequality constraints, equality constraints.
  std::vector<law::Law> objectives, inequalities, equalities;
  const Json& objs = json::get_array(json::require_member(doc, root, "objectives"), root_path("objectives"));
  if (objs.empty())
    throw Error(Errc::ParseError, "objectives is empty: a problem needs at least one objective",
                {.field = "objectives"});
  for (std::size_t i = 0; i < objs.size(); ++i) {
    const JsonPath path = root_path("objectives").element(i);
    objectives.push_back(read_expression(json::get_string(objs[i], path), path, context, options));
  }
  if (const Json* cons = json::optional_member(doc, "constraints")) {
    const Json& list = json::get_array(*cons, root_path("constraints"));
    for (std::size_t i = 0; i < list.size(); ++i) {
      const JsonPath path = root_path("constraints").element(i);
      if (!list[i].is_object()) json::type_error(list[i], path, "an object {\"expression\", \"type\"}");
      std::string type = "inequality";
      if (const Json* t = json::optional_member(list[i], "type")) type = json::get_string(*t, path.member("type"));
      if (type != "inequality" && type != "equality")
        throw Error(Errc::ParseError,
                    path.member("type").text + " = " + json::quote(type) +
                        " must be \"inequality\" (g <= 0) or \"equality\" (h = 0)",
                    path.where);
      const JsonPath expr_path = path.member("expression");
      const std::string expr = json::get_string(json::require_member(list[i], path, "expression"), expr_path);
      (type == "inequality" ? inequalities : equalities).push_back(read_expression(expr, expr_path, context, options));
    }
  }
  if (const Json* tol = json::optional_member(doc, "equality_tolerance"))
    problem.equality_tolerance = json::get_number(*tol, root_path("equality_tolerance"));
  if (const Json* ref = json::optional_member(doc, "reference")) {
    out.reference = json::get_number_array(*ref, root_path("reference"));
    if (out.reference->size() != objectives.size())
      throw Error(Errc::InvalidOption,
                  "reference has " + std::to_string(out.reference->size()) + " values but the file has " +
                      std::to_string(objectives.size()) + " objectives",
                  {.field = "reference"});
  }

  problem.objectives = objectives.size();
  problem.inequality_constraints = inequalities.size();
  problem.equality_constraints = equalities.size();
  std::vector<law::Law> outputs = std::move(objectives);
  outputs.insert(outputs.end(), inequalities.begin(), inequalities.end());
  outputs.insert(outputs.end(), equalities.begin(), equalities.end());
  const law::Tape tape = law::Tape::compile(outputs, options.parameters);
  // The tape is immutable and evaluate() uses a per-thread workspace, so the
  // function may run on several threads. Undefined values come out as NaN,
  // which the algorithms count as failed evaluations.
  problem.evaluate = [tape](std::span<const double> x, std::span<double> values) { (void)tape.evaluate(x, values); };
  problem.validate();
  return out;
}

ProblemFile read_problem_file(const std::filesystem::path& path) { return parse_problem_json(read_text_file(path)); }

}  // namespace hula::io
