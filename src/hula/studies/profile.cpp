// SPDX-License-Identifier: MIT
#include "hula/studies/profile.hpp"

#include <cmath>

#include "hula/core/error.hpp"
#include "hula/law/parser.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::studies {
namespace {

std::string sample_name(std::size_t i) { return "samples[" + std::to_string(i) + "]"; }

ErrorWhere sample_where(std::size_t i) {
  ErrorWhere w;
  w.field = "samples";
  w.index = i;
  return w;
}

// A planar NURBS graph (x(u) = u, y(u) = v(u)) as the law y(u).
law::Law graph_law(const nurbs::NurbsCurve& graph, const law::Context& context) {
  return law::term(context.curve(graph, context.parameter("u")), 2);
}

}  // namespace

std::string_view profile_abscissa_name(ProfileAbscissa a) noexcept {
  return a == ProfileAbscissa::Parameter ? "parameter" : "arclength";
}

ProfileAbscissa profile_abscissa_from_name(std::string_view name, std::string_view field) {
  if (name == "parameter") return ProfileAbscissa::Parameter;
  if (name == "arclength") return ProfileAbscissa::ArcLength;
  ErrorWhere w;
  w.field = std::string(field);
  throw Error(Errc::ParseError,
              std::string(field) + " = \"" + std::string(name) + "\": expected \"parameter\" or \"arclength\"", w);
}

Profile::Profile(law::Law f, std::string variable) : law_(std::move(f)), variable_(std::move(variable)) {
  const std::string inputs[1] = {variable_};
  const law::Law outputs[1] = {law_};
  tape_ = std::make_shared<const law::Tape>(law::Tape::compile(outputs, inputs));
}

Profile Profile::from_law(const law::Law& f, std::string_view variable) {
  if (f.dimension() != 1)
    throw Error(Errc::InvalidArgument, "a profile must be a scalar law of " + std::string(variable) + ", got a " +
                                           std::to_string(f.dimension()) + "-vector");
  return Profile(f, std::string(variable));
}

Profile Profile::from_samples(std::span<const double> u, std::span<const double> v, const law::Context& context) {
  if (u.size() != v.size())
    throw Error(Errc::InvalidArgument, "profile samples: " + std::to_string(u.size()) + " abscissae but " +
                                           std::to_string(v.size()) + " values");
  if (u.size() < 2) throw Error(Errc::InvalidArgument, "a sampled profile needs at least 2 samples", sample_where(0));
  for (std::size_t i = 0; i < u.size(); ++i) {
    if (!std::isfinite(u[i]) || !std::isfinite(v[i]))
      throw Error(Errc::NonFiniteInput, sample_name(i) + " is not finite", sample_where(i));
    if (i > 0 && !(u[i] > u[i - 1]))
      throw Error(Errc::InvalidArgument,
                  sample_name(i) + ": abscissa " + std::to_string(u[i]) + " does not increase from the previous one",
                  sample_where(i));
  }
  if (u.front() > 0.0 || u.back() < 1.0)
    throw Error(Errc::InvalidArgument,
                "profile samples cover [" + std::to_string(u.front()) + ", " + std::to_string(u.back()) +
                    "]; they must cover [0, 1]",
                sample_where(u.front() > 0.0 ? 0 : u.size() - 1));
  std::vector<double> knots;
  knots.reserve(u.size() + 2);
  knots.push_back(u.front());
  knots.insert(knots.end(), u.begin(), u.end());
  knots.push_back(u.back());
  std::vector<Vec3> points(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) points[i] = {u[i], v[i], 0.0};
  return Profile(graph_law(nurbs::NurbsCurve(1, std::move(knots), std::move(points), {}, 2), context), "u");
}

Profile Profile::from_bspline(int degree, std::span<const double> knots, std::span<const double> coefficients,
                              const law::Context& context) {
  if (degree < 1 || knots.size() != coefficients.size() + static_cast<std::size_t>(degree) + 1)
    throw Error(Errc::InvalidArgument, "bspline profile: degree " + std::to_string(degree) + " with " +
                                           std::to_string(coefficients.size()) + " coefficients needs " +
                                           std::to_string(coefficients.size() + degree + 1) + " knots, got " +
                                           std::to_string(knots.size()));
  for (std::size_t i = 0; i < coefficients.size(); ++i)
    if (!std::isfinite(coefficients[i]))
      throw Error(Errc::NonFiniteInput, "bspline profile: coefficients[" + std::to_string(i) + "] is not finite");
  // Greville abscissae make x(u) = u exactly, so the graph's y is the function.
  std::vector<Vec3> points(coefficients.size());
  for (std::size_t i = 0; i < coefficients.size(); ++i) {
    double g = 0.0;
    for (int k = 1; k <= degree; ++k) g += knots[i + static_cast<std::size_t>(k)];
    points[i] = {g / degree, coefficients[i], 0.0};
  }
  nurbs::NurbsCurve graph(degree, {knots.begin(), knots.end()}, std::move(points), {}, 2);
  const auto domain = graph.domain();
  if (domain.start > 0.0 || domain.end < 1.0)
    throw Error(Errc::InvalidArgument, "bspline profile: the knots span [" + std::to_string(domain.start) + ", " +
                                           std::to_string(domain.end) + "]; they must cover [0, 1]");
  return Profile(graph_law(graph, context), "u");
}

double Profile::operator()(double u) const {
  double out = 0.0;
  sample(std::span<const double>(&u, 1), std::span<double>(&out, 1));
  return out;
}

void Profile::sample(std::span<const double> u, std::span<double> out) const {
  if (u.size() != out.size())
    throw Error(Errc::InvalidArgument, "Profile::sample: " + std::to_string(u.size()) + " abscissae but " +
                                           std::to_string(out.size()) + " outputs");
  if (tape_->evaluate(u, out, std::span<std::uint8_t>{}) == 0) return;
  for (std::size_t i = 0; i < u.size(); ++i)
    if (std::isnan(out[i])) throw Error(Errc::OutOfDomain, "the profile is undefined at u = " + std::to_string(u[i]));
}

}  // namespace hula::studies
