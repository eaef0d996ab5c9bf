// SPDX-License-Identifier: MIT
#include "hula/optim/test_problems.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "hula/core/error.hpp"

namespace hula::optim {
namespace {
constexpr double kPi = std::numbers::pi;

void check_dimension(std::size_t d, std::size_t minimum, const char* problem) {
  if (d < minimum) {
    throw Error(Errc::InvalidOption,
                std::string(problem) + " dimension = " + std::to_string(d) + " must be >= " + std::to_string(minimum),
                {.field = "dimension"});
  }
}

Problem box(std::string name, std::size_t d, double lo, double hi, std::size_t objectives = 1) {
  Problem p;
  p.name = std::move(name);
  p.variables.assign(d, Variable{.lower = lo, .upper = hi});
  p.objectives = objectives;
  return p;
}
}  // namespace

Problem sphere(std::size_t d) {
  check_dimension(d, 1, "sphere");
  Problem p = box("sphere-" + std::to_string(d), d, -5.12, 5.12);
  p.evaluate = [](std::span<const double> x, std::span<double> f) {
    double s = 0.0;
    for (const double v : x) s += v * v;
    f[0] = s;
  };
  return p;
}

Problem rastrigin(std::size_t d) {
  check_dimension(d, 1, "rastrigin");
  Problem p = box("rastrigin-" + std::to_string(d), d, -5.12, 5.12);
  p.evaluate = [](std::span<const double> x, std::span<double> f) {
    double s = 10.0 * static_cast<double>(x.size());
    for (const double v : x) s += v * v - 10.0 * std::cos(2.0 * kPi * v);
    f[0] = s;
  };
  return p;
}

Problem rosenbrock(std::size_t d) {
  check_dimension(d, 2, "rosenbrock");
  Problem p = box("rosenbrock-" + std::to_string(d), d, -5.0, 10.0);
  p.evaluate = [](std::span<const double> x, std::span<double> f) {
    double s = 0.0;
    for (std::size_t i = 0; i + 1 < x.size(); ++i) {
      const double a = x[i + 1] - x[i] * x[i];
      const double b = 1.0 - x[i];
      s += 100.0 * a * a + b * b;
    }
    f[0] = s;
  };
  return p;
}

Problem ackley(std::size_t d) {
  check_dimension(d, 1, "ackley");
  Problem p = box("ackley-" + std::to_string(d), d, -15.0, 30.0);
  p.evaluate = [](std::span<const double> x, std::span<double> f) {
    double s1 = 0.0;
    double s2 = 0.0;
    for (const double v : x) {
      s1 += v * v;
      s2 += std::cos(2.0 * kPi * v);
    }
    const double n = static_cast<double>(x.size());
    f[0] = 20.0 + std::numbers::e - 20.0 * std::exp(-0.2 * std::sqrt(s1 / n)) - std::exp(s2 / n);
  };
  return p;
}

Problem schwefel(std::size_t d) {
  check_dimension(d, 1, "schwefel");
  Problem p = box("schwefel-" + std::to_string(d), d, -500.0, 500.0);
  p.evaluate = [](std::span<const double> x, std::span<double> f) {
    double s = 418.9828872724339 * static_cast<double>(x.size());
    for (const double v : x) s -= v * std::sin(std::sqrt(std::fabs(v)));
    f[0] = s;
  };
  return p;
}

Problem onemax(std::size_t d) {
  check_dimension(d, 1, "onemax");
  Problem p = box("onemax-" + std::to_string(d), d, 0.0, 1.0);
  for (auto& v : p.variables) v.precision = 1.0;
  p.evaluate = [](std::span<const double> x, std::span<double> f) {
    double ones = 0.0;
    for (const double v : x) ones += std::round(v);
    f[0] = static_cast<double>(x.size()) - ones;
  };
  return p;
}

Problem zdt(unsigned which, std::size_t dimension) {
  if (which != 1 && which != 2 && which != 3 && which != 4 && which != 6) {
    throw Error(Errc::InvalidOption, "zdt which = " + std::to_string(which) + " must be 1, 2, 3, 4 or 6",
                {.field = "which"});
  }
  const std::size_t d = dimension ? dimension : (which <= 3 ? 30 : 10);
  check_dimension(d, 2, "zdt");
  Problem p = box("zdt" + std::to_string(which), d, 0.0, 1.0, 2);
  if (which == 4) {
    for (std::size_t i = 1; i < d; ++i) p.variables[i] = Variable{.lower = -5.0, .upper = 5.0};
  }
  p.evaluate = [which](std::span<const double> x, std::span<double> f) {
    const std::size_t n = x.size();
    const double rest = static_cast<double>(n - 1);
    double s = 0.0;
    switch (which) {
      case 1:
      case 2:
      case 3: {
        for (std::size_t i = 1; i < n; ++i) s += x[i];
        const double g = 1.0 + 9.0 * s / rest;
        const double f1 = x[0];
        const double r = f1 / g;
        f[0] = f1;
        if (which == 1) f[1] = g * (1.0 - std::sqrt(r));
        if (which == 2) f[1] = g * (1.0 - r * r);
        if (which == 3) f[1] = g * (1.0 - std::sqrt(r) - r * std::sin(10.0 * kPi * f1));
        break;
      }
      case 4: {
        for (std::size_t i = 1; i < n; ++i) s += x[i] * x[i] - 10.0 * std::cos(4.0 * kPi * x[i]);
        const double g = 1.0 + 10.0 * rest + s;
        f[0] = x[0];
        f[1] = g * (1.0 - std::sqrt(x[0] / g));
        break;
      }
      default: {
        for (std::size_t i = 1; i < n; ++i) s += x[i];
        const double g = 1.0 + 9.0 * std::pow(s / rest, 0.25);
        const double f1 = 1.0 - std::exp(-4.0 * x[0]) * std::pow(std::sin(6.0 * kPi * x[0]), 6);
        const double r = f1 / g;
        f[0] = f1;
        f[1] = g * (1.0 - r * r);
        break;
      }
    }
  };
  return p;
}

Problem dtlz2(std::size_t objectives, std::size_t dimension) {
  if (objectives < 2) {
    throw Error(Errc::InvalidOption, "dtlz2 objectives = " + std::to_string(objectives) + " must be >= 2",
                {.field = "objectives"});
  }
  const std::size_t d = dimension ? dimension : objectives + 9;
  check_dimension(d, objectives, "dtlz2");
  Problem p = box("dtlz2-" + std::to_string(objectives), d, 0.0, 1.0, objectives);
  p.evaluate = [objectives](std::span<const double> x, std::span<double> f) {
    const std::size_t m = objectives;
    double g = 0.0;
    for (std::size_t i = m - 1; i < x.size(); ++i) g += (x[i] - 0.5) * (x[i] - 0.5);
    for (std::size_t k = 0; k < m; ++k) {
      // f_k = (1+g) prod_{i < m-1-k} cos(x_i pi/2) * sin(x_{m-1-k} pi/2) (k > 0).
      double v = 1.0 + g;
      for (std::size_t i = 0; i + 1 + k < m; ++i) v *= std::cos(x[i] * kPi / 2.0);
      if (k > 0) v *= std::sin(x[m - 1 - k] * kPi / 2.0);
      f[k] = v;
    }
  };
  return p;
}

Problem test_problem(std::string_view name, std::size_t dimension, std::size_t objectives) {
  const std::size_t d = dimension ? dimension : 10;
  if (name == "sphere") return sphere(d);
  if (name == "rastrigin") return rastrigin(d);
  if (name == "rosenbrock") return rosenbrock(d);
  if (name == "ackley") return ackley(d);
  if (name == "schwefel") return schwefel(d);
  if (name == "onemax") return onemax(d);
  if (name == "zdt1") return zdt(1, dimension);
  if (name == "zdt2") return zdt(2, dimension);
  if (name == "zdt3") return zdt(3, dimension);
  if (name == "zdt4") return zdt(4, dimension);
  if (name == "zdt6") return zdt(6, dimension);
  if (name == "dtlz2") return dtlz2(objectives ? objectives : 3, dimension);
  throw Error(Errc::InvalidArgument, "problem = \"" + std::string(name) + "\" is not a built-in test problem",
              {.field = "problem"});
}

}  // namespace hula::optim
