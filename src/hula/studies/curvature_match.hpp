// SPDX-License-Identifier: MIT
// Prescribed curvature profile matched over data points (thesis 8.2.1,
// appendix 5): the data points of a global C2 cubic through them
// (chord-length parameters normalised to [0, 1], natural ends unless a start
// or end tangent direction is fixed) are moved within per-coordinate bounds so
// that the curvature profile κ(u) comes close to a target κ*(u). The
// evaluation is eq. 31, e = (1/N) Σ_i |κ(u_i) − κ*(u_i)| over N samples
// u_i = i / (N − 1).
//
// Notation: t_k the data parameters (cumulative chord length / total), h_k =
// t_{k+1} − t_k, M_k = C''(t_k) the spline's moments; on span k,
// C(t) = a + b w + c w² + d w³ with w = t − t_k (de Boor, "A practical guide
// to splines", ch. IV). This is the same curve as nurbs::interpolate_cubic
// with chord-length parameters and the same end conditions (a test checks
// κ and τ against it to 1e-12); the moment form gives per-span polynomial
// coefficients from one tridiagonal solve into reused buffers, so a fitness
// evaluation allocates nothing (the hot path the thesis's GA spent a minute in).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/optim/problem.hpp"
#include "hula/studies/profile.hpp"
#include "hula/studies/validity.hpp"

namespace hula::studies {

/// Curvature (and torsion) samples of the C2 cubic spline through data points,
/// without building a NurbsCurve: the allocation-free fitness kernel.
class SplineProfileSampler {
 public:
  /// Reused buffers of one thread; sized on first use, never shrunk.
  struct Workspace {
    std::vector<double> t, h, diag, upper, rhs, moments, span_length, slopes;
    std::vector<double> coefficients;  // per span and coordinate: b, c, d
    std::vector<unsigned> span_of;     // the span of each sample
    // sample_jacobian: the factorisation of the moment system and one column's tangents.
    std::vector<double> pivot, factor_upper, dt, dh, dslope, drhs, dmoments;
  };

  /// @param point_count N >= 2 data points per evaluation
  /// @param dimension 2 (planar, z ignored) or 3
  /// @param sample_u abscissae in [0, 1], non-decreasing
  /// @param start_tangent fixed start tangent direction (clamped start, |C'(0)| = total chord length); unset = natural
  /// @param end_tangent fixed end tangent direction, as start_tangent; unset = natural
  /// @param abscissa Parameter: κ at t = u_i; ArcLength: κ where the arc length is u_i × the curve's length
  ///   (8-point Gauss–Legendre per span and Newton's method: about 10 times slower)
  /// @throws hula::Error(Errc::TooFewPoints) if point_count < 2
  /// @throws hula::Error(Errc::InvalidArgument) for a dimension other than 2 or 3, abscissae outside [0, 1] or
  ///   decreasing (naming the index), or a zero tangent direction
  /// @throws hula::Error(Errc::NonFiniteInput) for a non-finite abscissa or tangent
  SplineProfileSampler(std::size_t point_count, int dimension, std::vector<double> sample_u,
                       std::optional<Vec3> start_tangent = std::nullopt, std::optional<Vec3> end_tangent = std::nullopt,
                       ProfileAbscissa abscissa = ProfileAbscissa::Parameter);

  /// Number of data points the sampler expects.
  [[nodiscard]] std::size_t point_count() const noexcept { return n_; }
  /// 2 or 3.
  [[nodiscard]] int dimension() const noexcept { return dim_; }
  /// The sample abscissae u_i.
  [[nodiscard]] const std::vector<double>& abscissae() const noexcept { return u_; }
  /// What the abscissae measure.
  [[nodiscard]] ProfileAbscissa abscissa() const noexcept { return abscissa_; }
  /// The unit start / end tangent directions, if fixed.
  [[nodiscard]] const std::optional<Vec3>& start_tangent() const noexcept { return start_; }
  [[nodiscard]] const std::optional<Vec3>& end_tangent() const noexcept { return end_; }

  /// κ(u_i) and, if `tau` is not empty, τ(u_i) of the spline through `points`.
  /// κ = |C' × C''| / |C'|³ (unsigned, as the thesis's profiles); τ = (C' × C'') · C''' / |C' × C''|², NaN where
  /// |C' × C''| <= 1e-12 |C'|³ (κ vanishes: torsion undefined), 0 for dimension 2. No allocation once the workspace
  /// has been used with as many points.
  /// @param points point_count() points
  /// @param ws buffers (one per thread)
  /// @param kappa abscissae().size() values out
  /// @param tau empty, or abscissae().size() values out
  /// @returns false (outputs NaN) if two consecutive points coincide or a value is not finite
  /// @throws hula::Error(Errc::InvalidArgument) if a span's size is wrong
  bool sample(std::span<const Vec3> points, Workspace& ws, std::span<double> kappa, std::span<double> tau = {}) const;

  /// κ(u_i) and its exact derivatives ∂κ(u_i)/∂P_{k,c} with respect to chosen data-point coordinates
  /// (abscissa Parameter only): the tangent-linear form of sample(), differentiating the chord-length parameters,
  /// the moment system A(t) M = b(P, t) (A dM = db − dA M, solved with A's factorisation reused for every column)
  /// and κ = |C' × C''| / |C'|³ by the chain rule. Where C' × C'' = 0 (κ = 0, where unsigned κ has no derivative)
  /// the column entry is 0. Allocates only the workspace.
  /// @param points point_count() points
  /// @param ws buffers (one per thread)
  /// @param coordinates flat indices 3 k + c (point k, coordinate c < dimension()) of the columns
  /// @param kappa abscissae().size() values out
  /// @param jacobian abscissae().size() × coordinates.size() values out, row-major
  /// @returns false (outputs NaN) if two consecutive points coincide or a value is not finite
  /// @throws hula::Error(Errc::InvalidArgument) if a span's size is wrong, a coordinate is out of range or the
  ///   abscissa is ArcLength
  bool sample_jacobian(std::span<const Vec3> points, Workspace& ws, std::span<const std::size_t> coordinates,
                       std::span<double> kappa, std::span<double> jacobian) const;

  /// The same spline as a NurbsCurve (nurbs::interpolate_cubic with the chord-length parameters and the clamped
  /// derivatives this sampler uses), for output and figures.
  /// @throws hula::Error as nurbs::interpolate_cubic
  [[nodiscard]] nurbs::NurbsCurve curve(std::span<const Vec3> points) const;

 private:
  std::size_t n_;
  int dim_;
  std::vector<double> u_;
  std::optional<Vec3> start_, end_;
  ProfileAbscissa abscissa_;
};

/// The setup of a curvature-matching study.
struct CurvatureMatchSetup {
  /// Start data points (N >= 2), z = 0 when dimension = 2.
  std::vector<Vec3> points{};
  /// 2 (planar) or 3.
  int dimension = 2;
  /// Per-point lower offsets (the thesis's lower_limit): a free coordinate may go down to value − lower. >= 0.
  std::vector<Vec3> lower{};
  /// Per-point upper offsets (upper_limit): up to value + upper. >= 0. lower = upper = 0 fixes the coordinate.
  std::vector<Vec3> upper{};
  /// Fixed start tangent direction (clamped start); unset = natural start.
  std::optional<Vec3> start_tangent{};
  /// Fixed end tangent direction (clamped end); unset = natural end.
  std::optional<Vec3> end_tangent{};
  /// Target curvature profile κ*(u).
  std::optional<Profile> target{};
  /// Optional target torsion profile τ*(u) (for the curvature + torsion study).
  std::optional<Profile> torsion_target{};
  /// Proximity weights w_i >= 0 per data point (local edits stay local), or empty (default: none).
  /// The GA's curvature objective becomes e + Σ_i w_i |p_i − p_i⁰|² (p⁰ the start points; w in 1 / model unit³, so
  /// that the term is a curvature like e), and the least-squares refinement appends the residuals
  /// √w_i (x_j − x_j⁰) for each free coordinate j of point i. Reported distances stay pure curvature distances.
  std::vector<double> proximity{};
  /// The points the proximity regularisation pulls towards, one per point, or empty (default: `points`). The
  /// re-centred rounds of thesis 7.4.1 (recentred_setup) move `points` and keep the designer's start here.
  std::vector<Vec3> proximity_centre{};
  /// Samples N >= 2. Default 200.
  std::size_t samples = 200;
  /// Where the samples are: at the parameter (thesis, default) or at the normalised arc length.
  ProfileAbscissa abscissa = ProfileAbscissa::Parameter;
  /// What a valid design must satisfy (no self-intersection, no cusp, monotone curvature). Default: nothing.
  /// When something is required the Flexo problems carry it as inequality constraints (validity_constraints)
  /// and the studies refuse an invalid result with the reasons.
  ValidityRequirements validity{};

  /// @throws hula::Error as ValidityRequirements::validate
  /// @throws hula::Error(Errc::TooFewPoints) if fewer than 2 points
  /// @throws hula::Error(Errc::InvalidArgument) naming `proximity[i]` if negative or the count differs from the
  ///   points', and `proximity_centre` if its count differs; naming `lower[i]`/`upper[i]` (and the coordinate) for a
  ///   count mismatch, a negative offset (bounds that exclude the start value), any offset on points[0] (the start
  ///   point is fixed), a z offset in 2-D, no free coordinate at all; `samples` < 2; no target
  /// @throws hula::Error(Errc::NonFiniteInput) naming the point or offset that is NaN or infinite
  void validate() const;
};

/// Distances of one candidate from the targets.
struct MatchDistances {
  /// Mean |κ(u_i) − κ*(u_i)| (eq. 31).
  double mean = 0.0;
  /// Max |κ(u_i) − κ*(u_i)|.
  double max = 0.0;
  /// Mean |τ(u_i) − τ*(u_i)| over the samples where τ is defined (NaN without a torsion target).
  double torsion_mean = 0.0;
};

/// The matching problem: the free coordinates as design variables, the target samples precomputed once.
class CurvatureMatch {
 public:
  /// @throws hula::Error as CurvatureMatchSetup::validate, and Errc::OutOfDomain if the target is undefined at a sample
  explicit CurvatureMatch(CurvatureMatchSetup setup);

  /// The validated setup.
  [[nodiscard]] const CurvatureMatchSetup& setup() const noexcept { return setup_; }
  /// The sampler (abscissae u_i = i / (N − 1)).
  [[nodiscard]] const SplineProfileSampler& sampler() const noexcept { return sampler_; }
  /// κ*(u_i).
  [[nodiscard]] const std::vector<double>& target_samples() const noexcept { return target_; }
  /// τ*(u_i), empty without a torsion target.
  [[nodiscard]] const std::vector<double>& torsion_target_samples() const noexcept { return torsion_target_; }
  /// Number of free coordinates.
  [[nodiscard]] std::size_t dimension() const noexcept { return free_.size(); }
  /// Design variables named "points[i].x" with bounds [value − lower, value + upper].
  /// @param precision binary-coding resolution to set on each variable (0 = none)
  [[nodiscard]] std::vector<optim::Variable> variables(double precision = 0.0) const;
  /// The start values of the free coordinates.
  [[nodiscard]] std::vector<double> start_variables() const;
  /// Writes the data points for design variables x (the fixed coordinates from the setup).
  /// @param x dimension() values; @param out point count values
  void points_from(std::span<const double> x, std::span<Vec3> out) const;
  /// The index of the data point whose coordinate design variable j is; j < dimension().
  [[nodiscard]] std::size_t variable_point(std::size_t j) const { return free_.at(j).point; }
  /// The free coordinates of `points` in variable order (the inverse of points_from on the free set).
  /// @param points point count values
  [[nodiscard]] std::vector<double> variables_from(std::span<const Vec3> points) const;
  /// Mean curvature distance (eq. 31) of x; NaN if the spline is degenerate. No allocation once `ws` is warm.
  /// @param kappa scratch of sampler().abscissae().size() values
  [[nodiscard]] double mean_distance(std::span<const double> x, SplineProfileSampler::Workspace& ws,
                                     std::span<Vec3> points, std::span<double> kappa) const;
  /// Residuals r_i = κ(u_i) − κ*(u_i) of x; returns false if degenerate.
  bool residuals(std::span<const double> x, SplineProfileSampler::Workspace& ws, std::span<Vec3> points,
                 std::span<double> r) const;
  /// Whether residuals_jacobian applies (the sampler's abscissa is Parameter).
  [[nodiscard]] bool has_exact_jacobian() const noexcept { return sampler_.abscissa() == ProfileAbscissa::Parameter; }
  /// Residuals r_i = κ(u_i) − κ*(u_i) of x and their exact Jacobian ∂r_i/∂x_j (SplineProfileSampler::
  /// sample_jacobian), row-major samples × dimension(); returns false if degenerate.
  /// @throws hula::Error(Errc::InvalidArgument) if !has_exact_jacobian()
  bool residuals_jacobian(std::span<const double> x, SplineProfileSampler::Workspace& ws, std::span<Vec3> points,
                          std::span<double> r, std::span<double> jacobian) const;
  /// Curvature and torsion distances of x in one pass, for the two-objective (NSGA-II) study: no allocation once
  /// `ws` is warm. torsion_mean is NaN without a torsion target (τ is then not computed) or if τ is undefined at
  /// every sample; all three are NaN if the spline is degenerate.
  /// @param points, kappa, tau scratch of point count and sampler().abscissae().size() values
  [[nodiscard]] MatchDistances mean_distances(std::span<const double> x, SplineProfileSampler::Workspace& ws,
                                              std::span<Vec3> points, std::span<double> kappa,
                                              std::span<double> tau) const;
  /// All distances of x (allocates; for reports).
  [[nodiscard]] MatchDistances distances(std::span<const double> x) const;
  /// The validity of the spline through the data points of x against setup().validity (allocates; an empty
  /// check when nothing is required; a degenerate spline is invalid with that reason).
  [[nodiscard]] ValidityCheck validity(std::span<const double> x) const;
  /// Writes setup().validity.count() constraint values g ≤ 0 for the spline through `points` (NaN when the
  /// spline cannot be built); nothing when nothing is required. Allocates.
  void validity_constraints(std::span<const Vec3> points, std::span<double> out) const;
  /// κ(u_i) of x (allocates; for reports and figures).
  [[nodiscard]] std::vector<double> curvature_samples(std::span<const double> x) const;
  /// τ(u_i) of x, NaN where the torsion is undefined (allocates; for reports and figures).
  [[nodiscard]] std::vector<double> torsion_samples(std::span<const double> x) const;
  /// Σ_i w_i |p_i − p_i⁰|² of CurvatureMatchSetup::proximity for the points `points` (0 without weights), p⁰ the
  /// proximity centre.
  [[nodiscard]] double proximity_penalty(std::span<const Vec3> points) const;
  /// The design variables of the proximity centre (CurvatureMatchSetup::proximity_centre, else the start).
  [[nodiscard]] std::vector<double> proximity_variables() const;
  /// The single-objective Flexo problem "mean curvature distance" (+ the proximity penalty), with the validity
  /// requirements as inequality constraints; evaluation uses one workspace per thread (and allocates only for
  /// the validity checks) and refers to this object, which must outlive the problem.
  /// @param precision as variables()
  [[nodiscard]] optim::Problem problem(double precision = 0.0) const;

 private:
  CurvatureMatchSetup setup_;
  SplineProfileSampler sampler_;
  std::vector<double> target_, torsion_target_;
  struct Free {
    std::size_t point;
    std::size_t coordinate;
  };
  std::vector<Free> free_;
  std::vector<std::size_t> free_flat_;  // 3 point + coordinate of each free coordinate (sample_jacobian's columns)
};

/// The sample abscissae of every matching study: u_i = i / (samples − 1), i = 0 … samples − 1 (the last exactly 1).
/// @param samples >= 2
[[nodiscard]] std::vector<double> uniform_abscissae(std::size_t samples);

/// The curvature profile κ(u_i), u_i = i / (samples − 1), of the spline through `points` (natural ends unless
/// tangents are given): the "known curve" targets of the thesis's validation method.
/// @throws hula::Error as SplineProfileSampler, and Errc::CoincidentPoints if two consecutive points coincide
[[nodiscard]] std::vector<double> curvature_profile_of(std::span<const Vec3> points, int dimension, std::size_t samples,
                                                       std::optional<Vec3> start_tangent = std::nullopt,
                                                       std::optional<Vec3> end_tangent = std::nullopt,
                                                       ProfileAbscissa abscissa = ProfileAbscissa::Parameter);

/// What spline_profile_breaks reads off a curvature profile.
struct SplineProfileBreaks {
  /// 0, the interior data parameters ascending, 1.
  std::vector<double> parameters{};
  /// The samples with their sign changed past each zero crossing of the unsigned κ (an inflection), positive on
  /// the whole where the profile turns most: a signed curvature profile to integrate.
  std::vector<double> signed_samples{};
};

/// The data parameters of the cubic spline whose curvature profile `kappa` is (samples at uniform abscissae
/// u_i = i / (N − 1), as curvature_profile_of). The spline is C2, so κ is smooth between the data parameters and its
/// slope dκ/du jumps at them. On the ten samples around each sample interval, a cubic is fitted by least squares
/// against the cubic plus a kink J (i − ξ)₊ (ξ on a grid of 1/50 of the interval); the interval's score is the root
/// of the squares the kink explains. The strongest local maxima, none within four samples of another, are taken,
/// as many as `interior`. A local minimum of the unsigned κ that the straight lines through its two neighbours on
/// either side carry below zero is an inflection (κ crossing zero): its kink is not a data parameter, and the
/// signed samples change sign there.
/// @param kappa the profile samples (unsigned, as the thesis's)
/// @param interior the number of interior data parameters sought (data points − 2)
/// @param separation how many times stronger the weakest interval taken must be than the strongest left out
/// @returns the breaks; none when they cannot be told from the samples: a span would hold fewer than six samples,
///   a sample is not finite, or the weakest interval taken is not `separation` times stronger than the strongest
///   left out (a smooth profile, a law, noise). Accuracy: within 1.5 sample spacings, mostly a tenth (tests).
[[nodiscard]] std::optional<SplineProfileBreaks> spline_profile_breaks(std::span<const double> kappa,
                                                                       std::size_t interior, double separation = 2.0);

/// The torsion profile τ(u_i) of the 3-D spline through `points`, as curvature_profile_of.
/// @throws hula::Error as curvature_profile_of, and Errc::OutOfDomain naming u where τ is undefined (the
///   curvature vanishes there, as at a natural end)
[[nodiscard]] std::vector<double> torsion_profile_of(std::span<const Vec3> points, std::size_t samples,
                                                     std::optional<Vec3> start_tangent = std::nullopt,
                                                     std::optional<Vec3> end_tangent = std::nullopt,
                                                     ProfileAbscissa abscissa = ProfileAbscissa::Parameter);

}  // namespace hula::studies
