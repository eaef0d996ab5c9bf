// SPDX-License-Identifier: MIT
// `hula edit OPERATION CURVE -o OUT`: the kernel's shape-preserving and
// splitting operations on a NURBS curve file (thesis 5.5, The NURBS Book ch. 5):
// insert-knot (Boehm, A5.1), refine (A5.4), remove-knots (A5.8, within a
// tolerance), elevate (degree elevation), reduce-degree (within a tolerance),
// rebuild (a chosen degree and number of control points, deviation measured),
// split (knot insertion to
// multiplicity p), reverse and reparam (affine map of the knots), and to-nurbs (a law or natural curve
// converted to a NURBS within a tolerance, intrinsic::to_nurbs) and to-law (a NURBS written out as an exact law
// curve, io::law_from_nurbs). Each writes curve files and prints a JSON summary of the result. The edits are
// io::edit_curve's.
#include <memory>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/curve_edits.hpp"

namespace hula::cli {

namespace {

struct EditArgs {
  std::string curve;
  std::string output;
  std::string second;              // split: the curve after the split point
  double at = 0.0;                 // insert-knot, split, remove-knots
  int times = 1;                   // insert-knot, elevate, remove-knots
  double tolerance = 0.0;          // remove-knots, to-nurbs
  std::string knots;               // refine
  std::string domain;              // reparam
  int degree = 3;                  // rebuild
  std::size_t control_points = 0;  // rebuild
  std::size_t samples = 0;         // rebuild
};

// Runs the edit on the curve file and writes its curve(s): -o, and --second for split.
int run_edit(const EditArgs& a, io::CurveEditRequest request, const char* operation) {
  const curve::Curve file = io::read_curve_file(a.curve);
  const io::CurveEditAnswer answer = io::edit_curve(file, a.curve, request);
  io::write_curve_file(a.output, answer.curves.front());
  if (request.edit == io::CurveEdit::Split) io::write_curve_file(a.second, answer.curves.back());
  Json doc = Json::object();
  doc["operation"] = operation;
  doc.update(answer.report);
  if (request.edit == io::CurveEdit::Split) {
    doc["curves"] = Json::array({io::edited_curve_summary(a.output, answer.curves.front()),
                                 io::edited_curve_summary(a.second, answer.curves.back())});
    print_result(doc, io::is_std_stream(a.second) ? a.second : a.output);
  } else {
    doc["curve"] = io::edited_curve_summary(a.output, answer.curves.front());
    print_result(doc, a.output);
  }
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
  return run_edit(a, {.edit = io::CurveEdit::InsertKnot, .at = a.at, .times = a.times}, "insert-knot");
}

int run_refine(const EditArgs& a) {
  return run_edit(a, {.edit = io::CurveEdit::Refine, .knots = parse_number_list(a.knots, "knots")}, "refine");
}

// remove-knots: one knot (--at, up to --times) or every knot the tolerance allows.
int run_remove_knots(const EditArgs& a, bool one_knot) {
  return run_edit(a,
                  {.edit = one_knot ? io::CurveEdit::RemoveKnot : io::CurveEdit::RemoveKnots,
                   .at = a.at,
                   .times = a.times,
                   .tolerance = a.tolerance},
                  "remove-knots");
}

int run_elevate(const EditArgs& a) {
  return run_edit(a, {.edit = io::CurveEdit::Elevate, .times = a.times}, "elevate");
}

int run_reduce_degree(const EditArgs& a) {
  return run_edit(a, {.edit = io::CurveEdit::ReduceDegree, .tolerance = a.tolerance}, "reduce-degree");
}

int run_rebuild(const EditArgs& a) {
  return run_edit(
      a, {.edit = io::CurveEdit::Rebuild, .degree = a.degree, .control_points = a.control_points, .samples = a.samples},
      "rebuild");
}

int run_reverse(const EditArgs& a) { return run_edit(a, {.edit = io::CurveEdit::Reverse}, "reverse"); }

int run_reparam(const EditArgs& a) {
  const std::vector<double> d = parse_number_list(a.domain, "domain");
  if (d.size() != 2)
    throw Error(Errc::InvalidArgument, "--domain " + a.domain + ": needs two numbers a,b",
                ErrorWhere{.field = "domain"});
  return run_edit(a, {.edit = io::CurveEdit::Reparam, .domain = {d[0], d[1]}}, "reparam");
}

int run_split(const EditArgs& a) { return run_edit(a, {.edit = io::CurveEdit::Split, .at = a.at}, "split"); }

int run_to_nurbs(const EditArgs& a) {
  return run_edit(a, {.edit = io::CurveEdit::ToNurbs, .tolerance = a.tolerance}, "to-nurbs");
}

// to-law: the NURBS as a law curve file, with the conversion's report.
int run_to_law(const EditArgs& a) {
  const curve::Curve file = io::read_curve_file(a.curve);
  const io::LawConversionAnswer answer = io::law_from_nurbs(file, a.curve);
  io::write_curve_file(a.output, answer.curve);
  Json doc = Json::object();
  doc["operation"] = "to-law";
  doc.update(answer.report);
  Json curve = Json::object();
  curve["output"] = a.output;
  curve["kind"] = "law";
  curve["parameter"] = "t";
  curve["domain"] = Json::array({answer.curve.domain().start, answer.curve.domain().end});
  doc["curve"] = std::move(curve);
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
      "Edit a NURBS curve: insert-knot, refine, remove-knots, elevate, reduce-degree, rebuild, split, reverse, "
      "reparam, to-nurbs, to-law");
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
  CLI::App* rebuild =
      operation(edit, "rebuild",
                "Refit the curve with a chosen degree and number of control points (same ends and domain)", *a, out);
  rebuild->add_option("--degree", a->degree, "Degree of the new curve (default 3)")->check(CLI::Range(1, 64));
  rebuild->add_option("--control-points", a->control_points, "Control points of the new curve (>= degree + 1)")
      ->required();
  rebuild->add_option("--samples", a->samples,
                      "Samples of the curve fitted (default max(201, 10 x control points); >= control points)");
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
  CLI::App* to_law = operation(
      edit, "to-law", "Write a NURBS curve out as an exact law curve (a rational polynomial per knot span)", *a, out);
  return {edit,
          [a, insert, refine, remove, remove_at, elevate, reduce, rebuild, split, reverse, reparam, to_nurbs, to_law] {
            check_outputs(*a, split->parsed());
            if (to_nurbs->parsed()) return run_to_nurbs(*a);
            if (to_law->parsed()) return run_to_law(*a);
            if (insert->parsed()) return run_insert_knot(*a);
            if (refine->parsed()) return run_refine(*a);
            if (remove->parsed()) return run_remove_knots(*a, remove_at->count() > 0);
            if (elevate->parsed()) return run_elevate(*a);
            if (reduce->parsed()) return run_reduce_degree(*a);
            if (rebuild->parsed()) return run_rebuild(*a);
            if (split->parsed()) return run_split(*a);
            if (reverse->parsed()) return run_reverse(*a);
            return reparam->parsed() ? run_reparam(*a) : kExitUsage;
          }};
}

}  // namespace hula::cli
