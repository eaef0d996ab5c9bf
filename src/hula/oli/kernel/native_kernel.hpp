// SPDX-License-Identifier: MIT
// The native kernel backend: HulaHoops' own NURBS kernel (src/hula/nurbs) and
// differential geometry (src/hula/diffgeom) behind the Kernel interface.
#pragma once

#include "hula/oli/kernel/kernel.hpp"

namespace hula::oli {

/// The "native" backend. Stateless; use native_kernel() or make_kernel("native").
class NativeKernel final : public Kernel {
 public:
  [[nodiscard]] std::string_view name() const noexcept override { return "native"; }
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
