// SPDX-License-Identifier: MIT
// `hula edit OPERATION CURVE -o OUT`: the kernel's shape-preserving and
// splitting operations on a NURBS curve file (thesis 5.5, The NURBS Book ch. 5):
// insert-knot (Boehm, A5.1), refine (A5.4), remove-knots (A5.8, within a
// tolerance), elevate (degree elevation), reduce-degree (within a tolerance),
// split (knot insertion to
// multiplicity p), reverse and reparam (affine map of the knots), and to-nurbs (a law or natural curve
// converted to a NURBS within a tolerance, intrinsic::to_nurbs). Each writes curve files and prints a JSON
// summary of the result.
#include <memory>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/intrinsic/natural_curve.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/nurbs/elevate.hpp"
#include "hula/nurbs/knot_removal.hpp"
#include "hula/nurbs/refine.hpp"
#include "hula/nurbs/reparam.hpp"

namespace hula::cli {

namespace {

struct EditArgs {
  std::string curve;
  std::string output;
  std::string second;      // split: the curve after the split point
  double at = 0.0;         // insert-knot, split, remove-knots
  int times = 1;           // insert-knot, elevate, remove-knots
  double tolerance = 0.0;  // remove-knots, to-nurbs
  std::string knots;       // refine
  std::string domain;      // reparam
};

// The curve of a file; edits need the NURBS itself, not the stand-in of a law or natural curve.
nurbs::NurbsCurve read_nurbs(const std::string& path) {
  curve::Curve file = io::read_curve_file(path);
  if (file.has_exact_evaluation())
    throw Error(Errc::InvalidArgument,
                path + " is a " + std::string(file.kind_name()) + " curve: edit its NURBS form (hula edit to-nurbs " +
                    path + " --tolerance T -o FILE) instead",
                ErrorWhere{.field = "curve"});
  return file.nurbs();
}

Json summary(const std::string& path, const nurbs::NurbsCurve& c) {
  Json j = Json::object();
  j["output"] = path;
  j["degree"] = c.degree();
  j["control_points"] = c.control_points().size();
  Json knots = Json::array();
  for (double u : c.knots().values()) knots.push_back(u);
  j["knots"] = std::move(knots);
  j["domain"] = Json::array({c.domain().start, c.domain().end});
  return j;
}

int write_one(const EditArgs& a, const char* operation, const nurbs::NurbsCurve& result) {
  io::write_curve_file(a.output, result);
  Json doc = Json::object();
  doc["operation"] = operation;
  doc["curve"] = summary(a.output, result);
  print_result(doc, a.output);
  return kExitOk;
}

// Every output is checked before the curve is read or edited; split's two curves cannot share stdout.
void check_outputs(const EditArgs& a, bool split) {
  io::check_output_path(a.output, "--output");
  if (!split) return;
  io::check_output_path(a.second, "--second");
  if (io::is_std_stream(a.output) && io::is_std_stream(a.second))
    throw Error(Errc::InvalidArgument, "-o and --second are both - (standard output): give at most one of them as -",
                ErrorWhere{.field = "second"});
}

int run_insert_knot(const EditArgs& a) {
  return write_one(a, "insert-knot", nurbs::insert_knot(read_nurbs(a.curve), a.at, a.times));
}

int run_refine(const EditArgs& a) {
  const std::vector<double> x = parse_number_list(a.knots, "knots");
  return write_one(a, "refine", nurbs::refine_knots(read_nurbs(a.curve), x));
}

// remove-knots: one knot (--at, up to --times) or every knot the tolerance allows.
int run_remove_knots(const EditArgs& a, bool one_knot) {
  const nurbs::NurbsCurve curve = read_nurbs(a.curve);
  const nurbs::KnotRemovalResult r =
      one_knot ? nurbs::remove_knot(curve, a.at, a.times, a.tolerance) : nurbs::remove_knots(curve, a.tolerance);
  io::write_curve_file(a.output, r.curve);
  Json doc = Json::object();
  doc["operation"] = "remove-knots";
  doc["removed"] = r.removed;
  doc["error_bound"] = r.error_bound;
  doc["tolerance"] = a.tolerance;
  doc["curve"] = summary(a.output, r.curve);
  print_result(doc, a.output);
  return kExitOk;
}

int run_elevate(const EditArgs& a) {
  return write_one(a, "elevate", nurbs::elevate_degree(read_nurbs(a.curve), a.times));
}

int run_reduce_degree(const EditArgs& a) {
  const nurbs::DegreeReductionResult r = nurbs::reduce_degree(read_nurbs(a.curve), a.tolerance);
  io::write_curve_file(a.output, r.curve);
  Json doc = Json::object();
  doc["operation"] = "reduce-degree";
  doc["error_bound"] = r.error_bound;
  doc["bezier_bound"] = r.bezier_bound;
  doc["tolerance"] = a.tolerance;
  doc["curve"] = summary(a.output, r.curve);
  print_result(doc, a.output);
  return kExitOk;
}

int run_reverse(const EditArgs& a) { return write_one(a, "reverse", nurbs::reverse(read_nurbs(a.curve))); }

int run_reparam(const EditArgs& a) {
  const std::vector<double> d = parse_number_list(a.domain, "domain");
  if (d.size() != 2)
    throw Error(Errc::InvalidArgument, "--domain " + a.domain + ": needs two numbers a,b",
                ErrorWhere{.field = "domain"});
  return write_one(a, "reparam", nurbs::reparameterise(read_nurbs(a.curve), nurbs::Interval{d[0], d[1]}));
}

int run_split(const EditArgs& a) {
  const nurbs::SplitResult s = nurbs::split(read_nurbs(a.curve), a.at);
  io::write_curve_file(a.output, s.before);
  io::write_curve_file(a.second, s.after);
  Json doc = Json::object();
  doc["operation"] = "split";
  doc["at"] = a.at;
  doc["curves"] = Json::array({summary(a.output, s.before), summary(a.second, s.after)});
  print_result(doc, io::is_std_stream(a.second) ? a.second : a.output);
  return kExitOk;
}

int run_to_nurbs(const EditArgs& a) {
  const curve::Curve file = io::read_curve_file(a.curve);
  const intrinsic::CurveToNurbsResult r = intrinsic::to_nurbs(file, a.tolerance);
  io::write_curve_file(a.output, r.curve);
  Json doc = Json::object();
  doc["operation"] = "to-nurbs";
  doc["from"] = std::string(file.kind_name());
  doc["tolerance"] = a.tolerance;
  doc["max_deviation"] = r.max_deviation;
  doc["curve"] = summary(a.output, r.curve);
  print_result(doc, a.output);
  return kExitOk;
}

CLI::App* operation(CLI::App* edit, const char* name, const char* help, EditArgs& a, const char* output_help) {
  CLI::App* op = edit->add_subcommand(name, help);
  op->add_option("curve", a.curve, "NURBS curve file (JSON)")->required();
  op->add_option("-o,--output", a.output, output_help)->required();
  return op;
}

}  // namespace

Command add_edit(CLI::App& app) {
  auto a = std::make_shared<EditArgs>();
  CLI::App* edit = app.add_subcommand(
      "edit",
      "Edit a NURBS curve: insert-knot, refine, remove-knots, elevate, reduce-degree, split, reverse, reparam, "
      "to-nurbs");
  edit->require_subcommand(1);
  const char* out = "Curve file to write (atomically)";
  CLI::App* insert = operation(edit, "insert-knot", "Insert a knot (the curve is unchanged)", *a, out);
  insert->add_option("--at", a->at, "Knot value u inside the domain")->required();
  insert->add_option("--times", a->times, "Insertions r >= 1 (default 1); multiplicity stays <= degree")
      ->check(CLI::Range(1, 64));
  CLI::App* refine = operation(edit, "refine", "Insert several knots at once (the curve is unchanged)", *a, out);
  refine->add_option("--knots", a->knots, "Knot values u0,u1,... (non-decreasing, inside the domain)")->required();
  CLI::App* remove =
      operation(edit, "remove-knots", "Remove knots while the curve moves by at most --tolerance", *a, out);
  remove->add_option("--tolerance", a->tolerance, "Largest change of the curve allowed, model units (>= 0)")
      ->required();
  CLI::Option* remove_at =
      remove->add_option("--at", a->at, "Remove only this interior knot (default: every knot the tolerance allows)");
  remove->add_option("--times", a->times, "With --at: removals wanted >= 1 (default 1)")
      ->check(CLI::Range(1, 64))
      ->needs(remove_at);
  CLI::App* elevate = operation(edit, "elevate", "Raise the degree (the curve is unchanged)", *a, out);
  elevate->add_option("--times", a->times, "Degree increase >= 1 (default 1)")->check(CLI::Range(1, 64));
  CLI::App* reduce =
      operation(edit, "reduce-degree", "Lower the degree by one while the curve moves by at most --tolerance", *a, out);
  reduce->add_option("--tolerance", a->tolerance, "Largest change of the curve allowed, model units (>= 0)")
      ->required();
  CLI::App* split =
      operation(edit, "split", "Split at a parameter into two curve files", *a, "Curve file of the part before --at");
  split->add_option("--at", a->at, "Parameter strictly inside the domain")->required();
  split->add_option("--second", a->second, "Curve file of the part after --at")->required();
  CLI::App* reverse = operation(edit, "reverse", "Traverse the curve backwards on the same domain", *a, out);
  CLI::App* reparam = operation(edit, "reparam", "Map the curve's domain affinely onto a,b (same shape)", *a, out);
  reparam->add_option("--domain", a->domain, "New domain a,b with a < b")->required();
  CLI::App* to_nurbs =
      operation(edit, "to-nurbs", "Convert a law or natural (exact) curve to a NURBS within --tolerance", *a, out);
  to_nurbs->add_option("--tolerance", a->tolerance, "Largest distance NURBS-curve, model units, in (0, 1]")->required();
  return {edit, [a, insert, refine, remove, remove_at, elevate, reduce, split, reverse, reparam, to_nurbs] {
            check_outputs(*a, split->parsed());
            if (to_nurbs->parsed()) return run_to_nurbs(*a);
            if (insert->parsed()) return run_insert_knot(*a);
            if (refine->parsed()) return run_refine(*a);
            if (remove->parsed()) return run_remove_knots(*a, remove_at->count() > 0);
            if (elevate->parsed()) return run_elevate(*a);
            if (reduce->parsed()) return run_reduce_degree(*a);
            if (split->parsed()) return run_split(*a);
            if (reverse->parsed()) return run_reverse(*a);
            return reparam->parsed() ? run_reparam(*a) : kExitUsage;
          }};
}

}  // namespace hula::cli
