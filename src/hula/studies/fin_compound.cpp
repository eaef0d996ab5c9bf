// SPDX-License-Identifier: MIT
// Prescribed compound fins (thesis 8.3); see fin_compound.hpp for the maths.
#include "hula/studies/fin_compound.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/diffgeom/combescure.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/law/derive.hpp"
#include "hula/studies/detail/piecewise_fit.hpp"
#include "hula/studies/projection_edit.hpp"

namespace hula::studies {

namespace {

constexpr int kMaxSamples = 1000000;

// Tangent directions on the two sides of a knot that differ by more than this angle (radians) are a
// corner. The pieces joined by fit_on_spans meet with the law's exact derivative on both sides, so
// curves produced here stay far below it; a real corner is orders of magnitude above.
constexpr double kCornerAngle = 1e-8;

// Refuses a curve whose tangent turns at a knot: the offset by its normal would tear there (and the
// kernel's one-sided evaluation at the knot would hide the tear inside one piece of the fit).
void require_g1(const nurbs::NurbsCurve& curve, const char* field) {
  const nurbs::Interval d = curve.domain();
  const std::vector<double> knots = curve.knots().breakpoints();
  for (std::size_t i = 0; i < knots.size(); ++i) {
    const double u = knots[i];
    if (!(u > d.start && u < d.end) || curve.knots().multiplicity(u) < curve.degree()) continue;
    const Vec3 l = curve.derivatives(u, 1, {.side = nurbs::Side::Left})[1];
    const Vec3 r = curve.derivatives(u, 1, {.side = nurbs::Side::Right})[1];
    const double angle = std::atan2(norm(cross(l, r)), dot(l, r));
    if (!(angle <= kCornerAngle))
      throw Error(Errc::InvalidArgument,
                  std::string(field) + "'s tangent turns by " + format_number(angle) + " rad at the knot t = " +
                      format_number(u) + ": its normal fin compound would tear there (give a tangent-continuous curve)",
                  {.field = field, .index = i});
  }
}

// `count` parameters equally spaced over the domain, plus the interior knots, sorted.
std::vector<double> sample_parameters(const nurbs::NurbsCurve& curve, int count) {
  const nurbs::Interval d = curve.domain();
  std::vector<double> ts = detail::breakpoints(curve);
  for (int i = 1; i + 1 < count; ++i) {
    const double u = static_cast<double>(i) / (count - 1);
    ts.push_back(d.start * (1.0 - u) + d.end * u);
  }
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  return ts;
}

// The offset law C + sign · s (n × normalize(C')) of a NURBS curve C of "t".
law::Law offset_law(const nurbs::NurbsCurve& curve, const Vec3& n, double signed_scale) {
  law::Context ctx;
  const law::Law c = law::from_nurbs(curve, ctx, "t");
  const law::Law normal = law::cross(ctx.constant(n), law::normalize(law::derivative(c, "t", 1)));
  return c + signed_scale * normal;
}

LawCurveFit fit(const law::Law& law, const nurbs::NurbsCurve& along, const law::ToNurbsOptions& options,
                std::string_view field) {
  const std::vector<double> breaks = detail::breakpoints(along);
  law::ToNurbsResult r = detail::fit_on_spans(law, "t", breaks, options, field);
  return {law, std::move(r.curve), r.max_deviation};
}

void check_samples(int samples, const char* field) {
  if (samples < 2 || samples > kMaxSamples)
    throw Error(Errc::InvalidOption, std::string(field) + " = " + std::to_string(samples) + " must be in [2, 1000000]",
                {.field = field});
}

}  // namespace

void NormalCompoundOptions::validate() const {
  if (!std::isfinite(scale) || scale == 0.0)
    throw Error(Errc::InvalidOption, "scale = " + format_number(scale) + " must be finite and non-zero",
                {.field = "scale"});
  check_samples(samples, "samples");
  if (!(min_stretch > 0.0 && min_stretch < 1.0))
    throw Error(Errc::InvalidOption, "min_stretch = " + format_number(min_stretch) + " must be in (0, 1)",
                {.field = "min_stretch"});
  fit.validate();
}

void CombescureOptions::validate() const {
  if (!std::isfinite(c) || c == 0.0)
    throw Error(Errc::InvalidOption, "c = " + format_number(c) + " must be finite and non-zero", {.field = "c"});
  check_samples(samples, "samples");
  if (!(angular >= 0.0 && std::isfinite(angular)))
    throw Error(Errc::InvalidOption, "angular = " + format_number(angular) + " must be finite and >= 0",
                {.field = "angular"});
  fit.validate();
}

LawCurveFit normal_compound(const nurbs::NurbsCurve& curve, const NormalCompoundOptions& options) {
  options.validate();
  const nurbs::NurbsCurve projection = diffgeom::project(curve, options.plane);
  require_g1(projection, "curve");
  // Where 1 + s κ_s ≤ 0 the fins cross and Q runs backwards: Q + s n_Q is then not P, so a compound
  // that folds back is refused rather than returned as if it could be inverted.
  const std::vector<double> ts = sample_parameters(projection, options.samples);
  std::vector<diffgeom::FrenetPoint> fp(ts.size());
  diffgeom::FrenetOptions fo;
  fo.plane_normal = plane_normal(options.plane);
  diffgeom::frenet(projection, ts, fp, fo);
  for (const diffgeom::FrenetPoint& p : fp) {
    if (!p.tangent_defined)
      throw Error(Errc::InvalidArgument,
                  "curve's projection on " + std::string(diffgeom::plane_name(options.plane)) + " has " +
                      std::string(diffgeom::undefined_name(p.reason)) + " at t = " + format_number(p.t) +
                      ": its normal fin compound is undefined there",
                  {.field = "curve"});
    const double stretch = 1.0 + options.scale * p.signed_curvature;
    if (stretch < options.min_stretch)
      throw Error(Errc::InvalidArgument,
                  "curve's fins cross at t = " + format_number(p.t) + " on " +
                      std::string(diffgeom::plane_name(options.plane)) + ": 1 + s*kappa = " + format_number(stretch) +
                      " < min_stretch = " + format_number(options.min_stretch) +
                      " (the compound folds back there and no curve has it as compound; use a smaller |s|)",
                  {.field = "curve"});
  }
  // Q = P − s (n × T) (fin_compound.hpp).
  return fit(offset_law(projection, plane_normal(options.plane), -options.scale), projection, options.fit, "curve");
}

StretchReport compound_stretch(const nurbs::NurbsCurve& compound, const NormalCompoundOptions& options) {
  options.validate();
  const std::vector<double> ts = sample_parameters(compound, options.samples);
  std::vector<diffgeom::FrenetPoint> fp(ts.size());
  diffgeom::FrenetOptions fo;
  fo.plane_normal = plane_normal(options.plane);
  diffgeom::frenet(compound, ts, fp, fo);
  StretchReport report{1.0, ts.front()};
  bool first = true;
  for (const diffgeom::FrenetPoint& p : fp) {
    if (!p.tangent_defined)
      throw Error(Errc::InvalidArgument,
                  "compound has " + std::string(diffgeom::undefined_name(p.reason)) + " at t = " + format_number(p.t) +
                      ": its normal, and so the curve behind it, is undefined there",
                  {.field = "compound"});
    const double stretch = 1.0 - options.scale * p.signed_curvature;
    if (first || stretch < report.min_stretch) report = {stretch, p.t};
    first = false;
  }
  return report;
}

LawCurveFit curve_from_normal_compound(const nurbs::NurbsCurve& compound, const NormalCompoundOptions& options) {
  options.validate();
  require_planar(compound, options.plane, "compound");
  require_g1(compound, "compound");
  const StretchReport s = compound_stretch(compound, options);
  if (s.min_stretch < options.min_stretch)
    throw Error(Errc::InvalidArgument,
                "compound bends too tightly at t = " + format_number(s.at) + ": 1 - s*kappa_Q = " +
                    format_number(s.min_stretch) + " < min_stretch = " + format_number(options.min_stretch) +
                    " (its radius of curvature towards its normal is not larger than the fin scale s = " +
                    format_number(options.scale) +
                    ", so the curve P = Q + s*n_Q would reverse there and its own compound would differ from Q)",
                {.field = "compound"});
  // P = Q + s n_Q (fin_compound.hpp).
  return fit(offset_law(compound, plane_normal(options.plane), options.scale), compound, options.fit, "compound");
}

CompoundEditResult edit_normal_compound(const nurbs::NurbsCurve& curve, const nurbs::NurbsCurve& edited_compound,
                                        const NormalCompoundOptions& options) {
  options.validate();
  require_planar(edited_compound, options.plane, "compound");
  CompoundEditResult r{diffgeom::project(curve, options.plane), normal_compound(curve, options),
                       curve_from_normal_compound(edited_compound, options), curve,
                       compound_stretch(edited_compound, options)};
  // Forward check: the compound of the reconstructed (fitted) projection against the prescribed one,
  // at the same parameters (the offset keeps the compound's parameter).
  const std::vector<double> ts = sample_parameters(edited_compound, options.samples);
  std::vector<diffgeom::FrenetPoint> fp(ts.size());
  diffgeom::FrenetOptions fo;
  fo.plane_normal = plane_normal(options.plane);
  diffgeom::frenet(r.planar.curve, ts, fp, fo);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const Vec3 q = fp[i].position - options.scale * fp[i].signed_normal;
    r.forward_deviation = std::max(r.forward_deviation, distance(q, edited_compound.evaluate(ts[i])));
  }
  const ProjectionEditResult edit = edit_projection(curve, r.planar.curve, options.plane);
  r.curve = edit.curve;
  r.assembly_deviation = edit.max_deviation;
  return r;
}

namespace {

// Refuses a NURBS curve whose third derivative jumps at a knot (the compound would tear there).
void require_c3(const nurbs::NurbsCurve& curve, const char* field) {
  const nurbs::Interval d = curve.domain();
  const std::vector<double> knots = curve.knots().breakpoints();
  for (std::size_t i = 0; i < knots.size(); ++i) {
    const double u = knots[i];
    const int mult = curve.knots().multiplicity(u);
    if (u > d.start && u < d.end && curve.degree() - mult < 3)
      throw Error(Errc::InvalidArgument,
                  std::string(field) + " is only C" + std::to_string(curve.degree() - mult) + " at the knot " +
                      format_number(u) + " (degree " + std::to_string(curve.degree()) + ", multiplicity " +
                      std::to_string(mult) +
                      "): its torsion jumps there and the Combescure transform would tear; give a curve that is "
                      "C3 (a Bezier, a quintic with simple knots, or a law)",
                  {.field = field, .index = i});
  }
}

// Checks every sample of a law curve for a defined transform, then builds and fits it on `breaks`.
LawCurveFit combescure_checked(const law::Law& curve, std::string_view parameter, nurbs::Interval domain,
                               std::span<const double> breaks, const CombescureOptions& options, double c,
                               const char* field) {
  options.validate();
  if (curve.dimension() != 3)
    throw Error(Errc::InvalidArgument, std::string(field) + " must be a 3-D curve for the Combescure transform",
                {.field = field});
  const diffgeom::LawFrenet frenet(curve, std::string(parameter), domain);
  std::vector<double> ts(static_cast<std::size_t>(options.samples));
  for (int i = 0; i < options.samples; ++i) {
    const double u = static_cast<double>(i) / (options.samples - 1);
    ts[static_cast<std::size_t>(i)] = domain.start * (1.0 - u) + domain.end * u;
  }
  std::vector<diffgeom::FrenetPoint> fp(ts.size());
  frenet.at(ts, fp);
  std::size_t planar = 0;
  double planar_at = 0.0;
  for (const diffgeom::FrenetPoint& p : fp) {
    if (diffgeom::combescure(p, c, options.angular).defined) continue;
    if (!p.frame_defined)
      throw Error(Errc::InvalidArgument,
                  std::string(field) + " has " + std::string(diffgeom::undefined_name(p.reason)) + " at t = " +
                      format_number(p.t) + ": the Combescure transform (eq. 44, tau/kappa) is undefined there",
                  {.field = field});
    if (planar++ == 0) planar_at = p.t;
  }
  if (planar == fp.size())
    throw Error(Errc::InvalidArgument,
                std::string(field) +
                    " is planar (tau = 0 at every sample): the Combescure transform only shifts a planar curve "
                    "along its binormal (thesis 8.3); use the projection technique instead",
                {.field = field});
  if (planar > 0)
    throw Error(Errc::InvalidArgument,
                std::string(field) + " has zero torsion at t = " + format_number(planar_at) +
                    " (a planar piece): the Combescure transform is undefined there (thesis 8.3)",
                {.field = field});
  const law::Law q = diffgeom::combescure_law(curve, parameter, c);
  law::ToNurbsResult r = detail::fit_on_spans(q, parameter, breaks, options.fit, field);
  return {q, std::move(r.curve), r.max_deviation};
}

}  // namespace

LawCurveFit combescure_compound(const law::Law& curve, std::string_view parameter, nurbs::Interval domain,
                                const CombescureOptions& options) {
  const double breaks[] = {domain.start, domain.end};
  return combescure_checked(curve, parameter, domain, breaks, options, options.c, "curve");
}

LawCurveFit combescure_compound(const nurbs::NurbsCurve& curve, const CombescureOptions& options) {
  require_c3(curve, "curve");
  law::Context ctx;
  const std::vector<double> breaks = detail::breakpoints(curve);
  return combescure_checked(law::from_nurbs(curve, ctx, "t"), "t", curve.domain(), breaks, options, options.c, "curve");
}

// Q shares T, N, B and τ/κ with P, so P = Q − C (τ_Q/κ_Q T_Q + B_Q): the transform with −C.
LawCurveFit combescure_parent(const law::Law& compound, std::string_view parameter, nurbs::Interval domain,
                              const CombescureOptions& options) {
  const double breaks[] = {domain.start, domain.end};
  return combescure_checked(compound, parameter, domain, breaks, options, -options.c, "compound");
}

LawCurveFit combescure_parent(const nurbs::NurbsCurve& compound, const CombescureOptions& options) {
  require_c3(compound, "compound");
  law::Context ctx;
  const std::vector<double> breaks = detail::breakpoints(compound);
  return combescure_checked(law::from_nurbs(compound, ctx, "t"), "t", compound.domain(), breaks, options, -options.c,
                            "compound");
}

}  // namespace hula::studies
