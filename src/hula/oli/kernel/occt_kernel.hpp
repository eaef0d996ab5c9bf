// SPDX-License-Identifier: MIT
// The Open CASCADE kernel backend (Geom_BSplineCurve, GeomAPI_Interpolate,
// GeomLProp_CLProps, GCPnts_AbscissaPoint) behind the Kernel interface. Only
// built with Open CASCADE (HULA_WITH_OCCT). Torsion is not supported: OCCT
// has none, so it throws Errc::Unsupported (use with_fallback).
#pragma once

#include "hula/oli/kernel/kernel.hpp"

namespace hula::oli {

/// The "occt" backend. Stateless; use make_kernel("occt").
class OcctKernel final : public Kernel {
 public:
  [[nodiscard]] std::string_view name() const noexcept override { return "occt"; }
  [[nodiscard]] nurbs::NurbsCurve construct(int degree, std::vector<double> knots, std::vector<Vec3> control_points,
                                            std::vector<double> weights, int dimension) const override;
  [[nodiscard]] Vec3 evaluate(const nurbs::NurbsCurve& curve, double t) const override;
  [[nodiscard]] std::vector<Vec3> derivatives(const nurbs::NurbsCurve& curve, double t, int order) const override;
  [[nodiscard]] nurbs::NurbsCurve insert_knot(const nurbs::NurbsCurve& curve, double u, int times) const override;
  [[nodiscard]] nurbs::NurbsCurve elevate_degree(const nurbs::NurbsCurve& curve, int times) const override;
  [[nodiscard]] nurbs::SplitResult split(const nurbs::NurbsCurve& curve, double t) const override;
  [[nodiscard]] nurbs::NurbsCurve reverse(const nurbs::NurbsCurve& curve) const override;
  [[nodiscard]] nurbs::NurbsCurve interpolate(std::span<const Vec3> points,
                                              const KernelInterpolation& options) const override;
  [[nodiscard]] double curvature(const nurbs::NurbsCurve& curve, double t) const override;
  [[nodiscard]] double torsion(const nurbs::NurbsCurve& curve, double t) const override;
  [[nodiscard]] double arc_length(const nurbs::NurbsCurve& curve, double a, double b) const override;
};

}  // namespace hula::oli
