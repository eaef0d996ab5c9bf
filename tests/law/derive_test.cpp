// SPDX-License-Identifier: MIT
// Unit tests of symbolic derivatives: every function and operator against its
// closed-form derivative, and first and second derivatives against central
// finite differences with the explicit error bound
//   |D_h f − f'| ≤ h²/6 · max|f'''| + 2 ε max|f| / h   (Taylor + rounding),
// plus DAG compactness of the third derivative of a normalised vector and the
// NURBS leaf against NurbsCurve::derivatives.
#include "hula/law/derive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "hula/nurbs/interpolate.hpp"
#include "hula/testing/expect_error.hpp"
#include "law_test_util.hpp"

namespace hula::law {
namespace {

using test::eval;
using test::eval1;

struct DeriveCase {
  const char* name;
  std::function<Law(const Law&)> build;
  std::function<double(double)> derivative;  // closed form d/dt
  double lo, hi;                             // sample interval
};

constexpr double kEps = std::numeric_limits<double>::epsilon();

std::vector<DeriveCase> cases() {
  // u(t) = 0.3 + 0.5 t inside each function exercises the chain rule too.
  auto u = [](double t) { return 0.3 + 0.5 * t; };
  return {
      {"neg", [](const Law& t) { return -(t * t); }, [](double t) { return -2 * t; }, -2, 2},
      {"add", [](const Law& t) { return t * t + sin(t); }, [](double t) { return 2 * t + std::cos(t); }, -2, 2},
      {"sub", [](const Law& t) { return t * t - sin(t); }, [](double t) { return 2 * t - std::cos(t); }, -2, 2},
      {"mul", [](const Law& t) { return t * sin(t); }, [](double t) { return std::sin(t) + t * std::cos(t); }, -2, 2},
      {"div", [](const Law& t) { return sin(t) / (2.0 + t); },
       [](double t) { return (std::cos(t) * (2 + t) - std::sin(t)) / ((2 + t) * (2 + t)); }, -1, 2},
      {"pow_const", [](const Law& t) { return pow(1.5 + t, 2.5); },
       [](double t) { return 2.5 * std::pow(1.5 + t, 1.5); }, -1, 2},
      {"pow_var", [](const Law& t) { return pow(1.0 + t * t, t); },
       [](double t) {
         const double b = 1 + t * t;
         return std::pow(b, t) * (std::log(b) + t * 2 * t / b);
       },
       -1, 2},
      {"pow_int", [](const Law& t) { return pow(t, 3.0); }, [](double t) { return 3 * t * t; }, -2, 2},
      {"sqrt", [u](const Law& t) { return sqrt(0.3 + 0.5 * t); }, [u](double t) { return 0.25 / std::sqrt(u(t)); }, 0,
       3},
      {"exp", [](const Law& t) { return exp(0.3 + 0.5 * t); }, [u](double t) { return 0.5 * std::exp(u(t)); }, -2, 2},
      {"log", [](const Law& t) { return log(0.3 + 0.5 * t); }, [u](double t) { return 0.5 / u(t); }, 0, 3},
      {"sin", [](const Law& t) { return sin(0.3 + 0.5 * t); }, [u](double t) { return 0.5 * std::cos(u(t)); }, -3, 3},
      {"cos", [](const Law& t) { return cos(0.3 + 0.5 * t); }, [u](double t) { return -0.5 * std::sin(u(t)); }, -3, 3},
      {"tan", [](const Law& t) { return tan(0.3 + 0.5 * t); },
       [u](double t) { return 0.5 / (std::cos(u(t)) * std::cos(u(t))); }, -2, 2},
      {"asin", [](const Law& t) { return asin(0.3 * t); }, [](double t) { return 0.3 / std::sqrt(1 - 0.09 * t * t); },
       -2, 2},
      {"acos", [](const Law& t) { return acos(0.3 * t); }, [](double t) { return -0.3 / std::sqrt(1 - 0.09 * t * t); },
       -2, 2},
      {"atan", [](const Law& t) { return atan(0.3 + 0.5 * t); }, [u](double t) { return 0.5 / (1 + u(t) * u(t)); }, -3,
       3},
      {"atan2", [](const Law& t) { return atan2(sin(t), 2.0 + cos(t)); },
       [](double t) {
         const double y = std::sin(t), x = 2 + std::cos(t);
         return (x * std::cos(t) + y * std::sin(t)) / (x * x + y * y);
       },
       -3, 3},
      {"sinh", [](const Law& t) { return sinh(0.3 + 0.5 * t); }, [u](double t) { return 0.5 * std::cosh(u(t)); }, -2,
       2},
      {"cosh", [](const Law& t) { return cosh(0.3 + 0.5 * t); }, [u](double t) { return 0.5 * std::sinh(u(t)); }, -2,
       2},
      {"tanh", [](const Law& t) { return tanh(0.3 + 0.5 * t); },
       [u](double t) { return 0.5 / (std::cosh(u(t)) * std::cosh(u(t))); }, -2, 2},
      {"abs", [](const Law& t) { return abs(t - 0.05); }, [](double t) { return t > 0.05 ? 1.0 : -1.0; }, -2, 2},
      {"sign", [](const Law& t) { return sign(t - 0.05) * t; }, [](double t) { return t > 0.05 ? 1.0 : -1.0; }, -2, 2},
      {"min", [](const Law& t) { return min(t * t, 1.0 - t); }, [](double t) { return t * t <= 1 - t ? 2 * t : -1.0; },
       -2, 2},
      {"max", [](const Law& t) { return max(t * t, 1.0 - t); }, [](double t) { return t * t >= 1 - t ? 2 * t : -1.0; },
       -2, 2},
      {"piecewise", [](const Law& t) { return piecewise(less(t, t.context().constant(0.5)), sin(t), t * t); },
       [](double t) { return t < 0.5 ? std::cos(t) : 2 * t; }, -2, 2},
      {"dot", [](const Law& t) { return dot(vec(t, sin(t), 1.0 + t * 0.0 + t), vec(cos(t), t * t, t)); },
       [](double t) {
         // f = t cos t + t² sin t + (1 + t) t
         return std::cos(t) - t * std::sin(t) + 2 * t * std::sin(t) + t * t * std::cos(t) + 1 + 2 * t;
       },
       -2, 2},
      {"cross_z", [](const Law& t) { return term(cross(vec(t, sin(t), t), vec(cos(t), t * t, t)), 3); },
       [](double t) {
         // z = t·t² − sin t · cos t
         return 3 * t * t - std::cos(2 * t);
       },
       -2, 2},
      {"norm", [](const Law& t) { return norm(vec(cos(t), sin(t), t)); },
       [](double t) { return t / std::sqrt(1 + t * t); }, -2, 2},
      {"normalize_x", [](const Law& t) { return term(normalize(vec(t, t.context().constant(1.0))), 1); },
       [](double t) { return 1.0 / std::pow(1 + t * t, 1.5); }, -2, 2},
  };
}

// checks: d/dt of every supported function and operator against its closed form (1e-13 relative).
TEST(LawDerive, MatchesClosedForms) {
  for (const DeriveCase& c : cases()) {
    Context ctx;
    const Law t = ctx.parameter("t");
    const Law f = c.build(t);
    const Law df = derivative(f, "t");
    for (int i = 0; i <= 20; ++i) {
      const double x = c.lo + (c.hi - c.lo) * (i + 0.37) / 21.0;
      const double want = c.derivative(x);
      EXPECT_NEAR(eval1(df, x), want, 1e-13 * (1 + std::fabs(want))) << c.name << " at t = " << x;
    }
  }
}

// Central difference of g at x with its error bound h²/6·max|g'''| + 2ε·max|g|/h (max over [x−h, x+h]).
struct Fd {
  double value;
  double bound;
};
Fd central(const Law& g, double x, double h) {
  const Law g3 = derivative(g, "t", 3);
  double m3 = 0, m0 = 0;
  for (int k = -4; k <= 4; ++k) {
    const double y = x + h * k / 4.0;
    m3 = std::max(m3, std::fabs(eval1(g3, y)));
    m0 = std::max(m0, std::fabs(eval1(g, y)));
  }
  // 1.5 covers the sampling of max|g'''| on the interval (g''' varies by O(h) over it).
  return {(eval1(g, x + h) - eval1(g, x - h)) / (2 * h), 1.5 * (h * h / 6 * m3 + 2 * kEps * m0 / h) + 4 * kEps};
}

// checks: first and second derivatives against central finite differences within their error bound.
TEST(LawDerive, MatchesFiniteDifferencesWithinBound) {
  const double h = 1e-4;
  for (const DeriveCase& c : cases()) {
    Context ctx;
    const Law t = ctx.parameter("t");
    const Law f = c.build(t);
    const Law df = derivative(f, "t");
    const Law d2f = derivative(f, "t", 2);
    for (int i = 0; i <= 10; ++i) {
      const double x = c.lo + (c.hi - c.lo) * (i + 0.41) / 11.0;
      // skip kinks and switches within h (abs, sign, min, max, piecewise)
      bool near_kink = false;
      for (double k : {0.05, 0.5, 0.6180339887498949, -1.618033988749895})
        near_kink = near_kink || std::fabs(x - k) < 2 * h;
      if (near_kink) continue;
      const Fd d1 = central(f, x, h);
      EXPECT_LE(std::fabs(d1.value - eval1(df, x)), d1.bound) << c.name << " f' at " << x;
      const Fd d2 = central(df, x, h);
      EXPECT_LE(std::fabs(d2.value - eval1(d2f, x)), d2.bound) << c.name << " f'' at " << x;
    }
  }
}

// checks: the third derivative of normalize(v) stays compact (memoised, hash-consed) and matches
// finite differences of the second derivative.
TEST(LawDerive, ThirdDerivativeOfNormalizeIsCompact) {
  Context ctx;
  const Law t = ctx.parameter("t");
  const Law v = vec(cos(t) + t * t, sin(2.0 * t), exp(t / 3.0));
  const Law n = normalize(v);
  const std::size_t s0 = Context::size(n);
  const std::size_t s1 = Context::size(derivative(n, "t", 1));
  const std::size_t s2 = Context::size(derivative(n, "t", 2));
  const std::size_t s3 = Context::size(derivative(n, "t", 3));
  RecordProperty("sizes",
                 std::to_string(s0) + " " + std::to_string(s1) + " " + std::to_string(s2) + " " + std::to_string(s3));
  EXPECT_LE(s3, 400U) << s0 << " " << s1 << " " << s2 << " " << s3;
  // growth per order is bounded (no doubling): s3 - s2 is at most twice s2 - s1 plus slack
  EXPECT_LE(s3 - s2, 2 * (s2 - s1) + 40);
  const Law d2 = derivative(n, "t", 2);
  const Law d3 = derivative(n, "t", 3);
  for (double x : {-1.0, 0.2, 1.3}) {
    const double h = 1e-5;
    for (int k = 1; k <= 3; ++k) {
      const Law c2 = term(d2, k);
      const double fd = (eval1(c2, x + h) - eval1(c2, x - h)) / (2 * h);
      EXPECT_NEAR(fd, eval(d3, x)[static_cast<std::size_t>(k - 1)], 1e-5 * (1 + std::fabs(fd)));
    }
  }
}

// checks: derivatives of any order of t^5 against 5!/(5-k)! t^(5-k), and w.r.t. another parameter.
TEST(LawDerive, AnyOrderAnyParameter) {
  Context ctx;
  const Law t = ctx.parameter("t");
  const Law s = ctx.parameter("s");
  const Law f = pow(t, 5.0) * s;
  double coef = 1;
  for (int k = 0; k <= 6; ++k) {
    const Law d = derivative(f, "t", k);
    const double want = k <= 5 ? coef * std::pow(1.5, 5 - k) : 0.0;
    const Law ds = substitute(d, "s", ctx.constant(2.0));
    EXPECT_NEAR(eval1(ds, 1.5), 2.0 * want, 1e-12 * (1 + want)) << k;
    if (k < 5) coef *= (5 - k);
  }
  EXPECT_EQ(derivative(f, "s"), pow(t, 5.0));
  EXPECT_EQ(derivative(f, "u"), ctx.constant(0.0));
  EXPECT_EQ(derivative(vec(t, t, t), "u").dimension(), 3);
  HULA_EXPECT_ERROR(derivative(f, "t", -1), Errc::InvalidArgument, "order must be >= 0, got -1");
}

// checks: the NURBS leaf's derivatives (chain rule through the argument) against NurbsCurve::derivatives.
TEST(LawDerive, NurbsLeafUsesKernelDerivatives) {
  std::vector<Vec3> pts{{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {4, 0, 2}, {5, 3, 1}};
  const nurbs::NurbsCurve curve = nurbs::interpolate_cubic(pts);
  Context ctx;
  const Law t = ctx.parameter("t");
  const Law c = ctx.curve(curve, t * t, "spine");
  const Law d1 = derivative(c, "t");
  const Law d2 = derivative(c, "t", 2);
  for (double x : {0.1, 0.5, 0.9}) {
    const auto k = curve.derivatives(x * x, 2);
    const auto v1 = eval(d1, x);
    const auto v2 = eval(d2, x);
    for (std::size_t j = 0; j < 3; ++j) {
      EXPECT_NEAR(v1[j], k[1][j] * 2 * x, 1e-12 * (1 + std::fabs(v1[j])));
      EXPECT_NEAR(v2[j], k[2][j] * 4 * x * x + k[1][j] * 2, 1e-11 * (1 + std::fabs(v2[j])));
    }
  }
  EXPECT_TRUE(std::isnan(eval(c, 1.5)[0]));  // outside the domain [0, 1]: undefined
}

}  // namespace
}  // namespace hula::law

namespace hula::law {
namespace {

// checks: runaway derivative orders stop with a documented InvalidArgument (DAG limits) instead of
// exhausting memory or the stack.
TEST(LawDerive, DerivativeGrowthIsBounded) {
  Context ctx;
  const Law n = normalize(vec(cos(ctx.parameter("t")), sin(ctx.parameter("t")), exp(ctx.parameter("t") / 3.0)));
  HULA_EXPECT_ERROR(derivative(n, "t", 5000), Errc::InvalidArgument, "limit");
  EXPECT_LE(ctx.node_count(), kMaxNodes);
}

}  // namespace
}  // namespace hula::law
