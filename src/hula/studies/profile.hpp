// SPDX-License-Identifier: MIT
// A target profile: a scalar function v(u) on [0, 1], the "curvature profile"
// a designer prescribes in thesis 8.2 (Figure 75) — or a torsion profile. The
// abscissa u is the curve's parameter normalised to [0, 1] (the thesis's
// convention, appendix 5 reparameterises every candidate to [0, 1]) or its
// arc length normalised by the length; the study says which.
//
// Three sources, one representation (a scalar law of `u`, compiled once):
//   - a law expression of u, e.g. "0.05 + 0.02*sin(pi*u)";
//   - samples (u_i, v_i), joined linearly (exact at the samples, no overshoot);
//   - a B-spline function sum_i N_i,p(u) c_i (a "NURBS function").
// Study files write them as {"law": "..."}, {"samples": [[u, v], ...]},
// {"csv": "path"} (two columns u, v) or {"bspline": {"degree", "knots",
// "coefficients"}}; io/profile_file.hpp reads them.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "hula/law/expr.hpp"
#include "hula/law/tape.hpp"

namespace hula::studies {

/// What the abscissa u of a profile measures along the curve.
enum class ProfileAbscissa {
  /// The curve parameter mapped linearly onto [0, 1] (thesis 8.2.1, appendix 5).
  Parameter,
  /// Arc length divided by the curve's length.
  ArcLength,
};

/// "parameter" | "arclength".
[[nodiscard]] std::string_view profile_abscissa_name(ProfileAbscissa a) noexcept;
/// @throws hula::Error(Errc::ParseError) naming `field` for any other name
[[nodiscard]] ProfileAbscissa profile_abscissa_from_name(std::string_view name, std::string_view field);

/// A scalar function of u on [0, 1]. Immutable; cheap to copy; evaluation is
/// thread-safe.
class Profile {
 public:
  /// A law of one parameter.
  /// @param f a scalar law whose only parameter (if any) is `variable`
  /// @throws hula::Error(Errc::InvalidArgument) if f is not scalar or uses another parameter
  [[nodiscard]] static Profile from_law(const law::Law& f, std::string_view variable = "u");
  /// Samples joined linearly. They must cover [0, 1].
  /// @param u strictly increasing abscissae, at least 2, u.front() <= 0 and u.back() >= 1
  /// @param v values, as many as u, all finite
  /// @throws hula::Error(Errc::InvalidArgument) naming `samples[i]` for a count mismatch,
  ///   fewer than 2 samples, a non-increasing abscissa or one that leaves [0, 1] uncovered
  /// @throws hula::Error(Errc::NonFiniteInput) naming `samples[i]` for a NaN or infinite value
  [[nodiscard]] static Profile from_samples(std::span<const double> u, std::span<const double> v,
                                            const law::Context& context = law::Context{});
  /// A B-spline function of degree p: knots (clamped, covering [0, 1]) and n coefficients.
  /// @throws hula::Error as nurbs::KnotVector / NurbsCurve construction (naming the knots),
  ///   and Errc::InvalidArgument if the domain does not cover [0, 1]
  [[nodiscard]] static Profile from_bspline(int degree, std::span<const double> knots,
                                            std::span<const double> coefficients,
                                            const law::Context& context = law::Context{});

  /// The profile as a scalar law of variable() (for exact derivatives, integration and
  /// the natural-equation solver).
  [[nodiscard]] const law::Law& law() const noexcept { return law_; }
  /// The name of the law's parameter.
  [[nodiscard]] const std::string& variable() const noexcept { return variable_; }
  /// v(u).
  /// @throws hula::Error(Errc::OutOfDomain) naming u if the value is undefined there
  [[nodiscard]] double operator()(double u) const;
  /// v at many abscissae; no allocation per point.
  /// @param u abscissae; @param out as many values
  /// @throws hula::Error(Errc::OutOfDomain) naming the first u where the value is undefined
  /// @throws hula::Error(Errc::InvalidArgument) if the sizes differ
  void sample(std::span<const double> u, std::span<double> out) const;

 private:
  Profile(law::Law f, std::string variable);
  law::Law law_;
  std::string variable_;
  std::shared_ptr<const law::Tape> tape_;
};

}  // namespace hula::studies
