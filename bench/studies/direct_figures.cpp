// SPDX-License-Identifier: MIT
// Writes the figures of docs/studies/direct-reconstruction.md and prints the
// JSON summaries whose numbers the page quotes: a perturbed arc target
// κ*(u) = 0.5 + 0.1 sin(2πu) (L = 5) reconstructed freely (initial value) and
// held to the unperturbed arc's end point and tangent (boundary value), its
// curvature profiles, and the same for a perturbed helix (x–y projection).
//
// Run: cmake --build build/bench -j 1 --target studies_direct_figures
//      ./build/bench/bench/studies/studies_direct_figures docs/figures/studies/direct-reconstruction
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "hula/io/match_study_file.hpp"
#include "hula/io/svg.hpp"
#include "hula/law/parser.hpp"
#include "hula/studies/direct_reconstruction.hpp"

namespace {

using namespace hula;
using namespace hula::studies;

struct Polyline {
  std::vector<double> x, y;
};

Polyline trace(const intrinsic::IntrinsicCurve& c, int n = 400) {
  Polyline p;
  for (int i = 0; i <= n; ++i) {
    const Vec3 q = c.evaluate(c.length() * i / n).position;
    p.x.push_back(q.x);
    p.y.push_back(q.y);
  }
  return p;
}

void write(const std::filesystem::path& file, const io::SvgFigure& fig) {
  std::ofstream out(file);
  out << fig.render();
  std::cout << "wrote " << file.string() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : ".";
  std::filesystem::create_directories(dir);
  law::Context ctx;
  law::ParseOptions po;
  po.parameters = {"u"};
  const auto profile = [&](const char* text) { return Profile::from_law(law::parse(text, ctx, po), "u"); };

  // Planar: perturbed arc.
  const double R = 2.0, L = 5.0;
  const Vec3 end{R * std::sin(L / R), R * (1.0 - std::cos(L / R)), 0.0};
  const Vec3 end_tangent{std::cos(L / R), std::sin(L / R), 0.0};
  const Profile target = profile("0.5 + 0.1*sin(2*pi*u)");
  const DirectReconstructionResult arc = reconstruct_direct({.curvature = profile("0.5"), .length = L});
  const DirectReconstructionResult ivp = reconstruct_direct({.curvature = target, .length = L});
  const DirectReconstructionResult bvp =
      reconstruct_direct({.curvature = target, .length = L, .end_point = end, .end_tangent = end_tangent});
  std::cout << "perturbed arc, IVP: " << io::direct_reconstruction_summary(ivp).dump() << "\n";
  std::cout << "perturbed arc, BVP: " << io::direct_reconstruction_summary(bvp).dump() << "\n";
  {
    io::SvgFigure fig(900, 520);
    fig.set_title("kappa* = 0.5 + 0.1 sin(2 pi u), L = 5: free end vs held to the arc's end");
    fig.set_equal_aspect(true);
    const Polyline a = trace(arc.curve), f = trace(ivp.curve), b = trace(bvp.curve);
    fig.add_polyline(a.x, a.y, {.stroke = "#888888", .width = 1.0, .dash = "6 4"}, "arc R = 2");
    fig.add_polyline(f.x, f.y, {.stroke = "#1f77b4"}, "target, free end");
    fig.add_polyline(b.x, b.y, {.stroke = "#d62728"}, "end point + tangent held");
    const double ex[1] = {end.x}, ey[1] = {end.y};
    fig.add_points(ex, ey, {.stroke = "#000000"}, 4.0, "prescribed end");
    write(dir / "perturbed-arc.svg", fig);
  }
  {
    io::SvgFigure fig(900, 400);
    fig.set_title("curvature profiles against u = s / L");
    fig.set_axes("u", "kappa");
    std::vector<double> u, k_target, k_bvp, k_arc;
    const intrinsic::IntrinsicCurve& c = bvp.curve;
    for (int i = 0; i <= 200; ++i) {
      u.push_back(i / 200.0);
      k_target.push_back(target(u.back()));
      k_bvp.push_back(c.evaluate(u.back() * L).curvature);
      k_arc.push_back(0.5);
    }
    fig.add_polyline(u, k_arc, {.stroke = "#888888", .width = 1.0, .dash = "6 4"}, "arc 1/R");
    fig.add_polyline(u, k_target, {.stroke = "#1f77b4"}, "target kappa*");
    fig.add_polyline(u, k_bvp, {.stroke = "#d62728"}, "kappa* + delta kappa (boundary value)");
    write(dir / "perturbed-arc-curvature.svg", fig);
  }

  // Space: perturbed helix held to the helix's end.
  const double k0 = 0.8, t0 = 0.4, Ls = 10.0;
  const double rho = k0 / (k0 * k0 + t0 * t0), h = t0 / (k0 * k0 + t0 * t0), cc = std::hypot(rho, h);
  const auto point = [&](double s) { return Vec3{rho * std::cos(s / cc), rho * std::sin(s / cc), h * s / cc}; };
  const auto tangent = [&](double s) { return Vec3{-rho * std::sin(s / cc), rho * std::cos(s / cc), h} / cc; };
  const intrinsic::StartFrame start{point(0.0), tangent(0.0), Vec3{-1.0, 0.0, 0.0}};
  const Profile kt = profile("0.8 + 0.05*sin(2*pi*u)"), tt = profile("0.4 - 0.05*u");
  const DirectReconstructionResult hivp =
      reconstruct_direct({.curvature = kt, .torsion = tt, .length = Ls, .start = start});
  const DirectReconstructionResult hbvp = reconstruct_direct({.curvature = kt,
                                                              .torsion = tt,
                                                              .length = Ls,
                                                              .start = start,
                                                              .end_point = point(Ls),
                                                              .end_tangent = tangent(Ls)});
  std::cout << "perturbed helix, IVP: " << io::direct_reconstruction_summary(hivp).dump() << "\n";
  std::cout << "perturbed helix, BVP: " << io::direct_reconstruction_summary(hbvp).dump() << "\n";
  {
    io::SvgFigure fig(900, 520);
    fig.set_title("helix kappa = 0.8, tau = 0.4 perturbed, L = 10 (x-z view)");
    fig.set_equal_aspect(true);
    Polyline hx;
    for (int i = 0; i <= 400; ++i) {
      const Vec3 q = point(Ls * i / 400.0);
      hx.x.push_back(q.x);
      hx.y.push_back(q.z);
    }
    const auto xz = [](const intrinsic::IntrinsicCurve& c) {
      Polyline p;
      for (int i = 0; i <= 400; ++i) {
        const Vec3 q = c.evaluate(c.length() * i / 400.0).position;
        p.x.push_back(q.x);
        p.y.push_back(q.z);
      }
      return p;
    };
    const Polyline f = xz(hivp.curve), b = xz(hbvp.curve);
    fig.add_polyline(hx.x, hx.y, {.stroke = "#888888", .width = 1.0, .dash = "6 4"}, "helix");
    fig.add_polyline(f.x, f.y, {.stroke = "#1f77b4"}, "target, free end");
    fig.add_polyline(b.x, b.y, {.stroke = "#d62728"}, "end point + tangent held");
    const Vec3 e = point(Ls);
    const double ex[1] = {e.x}, ey[1] = {e.z};
    fig.add_points(ex, ey, {.stroke = "#000000"}, 4.0, "prescribed end");
    write(dir / "perturbed-helix.svg", fig);
  }
  return 0;
}
