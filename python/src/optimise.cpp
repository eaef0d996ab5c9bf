// SPDX-License-Identifier: MIT
// Flexo from Python: a problem is either a built-in test problem (name) or a
// Python callable evaluating a whole batch at once, a NumPy (n, d) array in,
// an (n, k) array of objectives then constraints out
// (optim::Problem::evaluate_many). The algorithms run with the GIL released;
// the callable re-acquires it once per generation. An exception raised by the
// callable ends the run and reaches the caller unchanged, with its traceback.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "hula/core/error.hpp"
#include "hula/io/optimise_request.hpp"
#include "hula/io/run_report_json.hpp"
#include "hula/optim/run_log.hpp"
#include "hula/optim/solve.hpp"
#include "hula/optim/test_problems.hpp"
#include "interrupt.hpp"

namespace hula::python {

namespace py = pybind11;

namespace {

// Reads the options dict, refusing keys no algorithm reads.
class Options {
 public:
  explicit Options(const py::dict& d) : d_(d) {}
  template <class T>
  std::optional<T> get(const char* key) {
    used_.insert(key);
    if (!d_.contains(key) || d_[key].is_none()) return std::nullopt;
    try {
      return d_[key].cast<T>();
    } catch (const py::cast_error&) {
      throw Error(Errc::InvalidOption,
                  std::string(key) + " = " + py::repr(d_[key]).cast<std::string>() + " has the wrong type",
                  {.field = key});
    }
  }
  void check_all_used(const std::string& algorithm) const {
    for (const auto& [key, value] : d_) {
      const auto k = key.cast<std::string>();
      if (!used_.contains(k)) {
        throw Error(Errc::InvalidOption, k + " is not an option of algorithm \"" + algorithm + "\"", {.field = k});
      }
    }
  }

 private:
  py::dict d_;
  std::set<std::string> used_;
};

optim::RunSettings run_settings(Options& o) {
  optim::RunSettings r;
  r.seed = o.get<std::uint64_t>("seed").value_or(0);
  r.threads = o.get<std::size_t>("threads").value_or(1);
  r.stop.generations = o.get<std::size_t>("generations").value_or(100);
  r.stop.max_evaluations = o.get<std::size_t>("max_evaluations").value_or(0);
  r.stop.target = o.get<double>("target");
  r.stop.stagnation_generations = o.get<std::size_t>("stagnation_generations").value_or(0);
  r.stop.wall_time_seconds = o.get<double>("wall_time").value_or(0.0);
  return r;
}

py::array rows(const std::vector<optim::Solution>& s, bool variables, std::size_t width) {
  Doubles a({static_cast<py::ssize_t>(s.size()), static_cast<py::ssize_t>(width)});
  for (std::size_t i = 0; i < s.size(); ++i) {
    const std::vector<double>& v = variables ? s[i].variables : s[i].objectives;
    std::copy(v.begin(), v.end(), a.mutable_data() + i * width);
  }
  return a;
}

// The island options; none when "islands" is absent or 0 (one population).
std::optional<optim::IslandOptions> island_options(Options& o) {
  optim::IslandOptions i;
  i.islands = o.get<std::size_t>("islands").value_or(0);
  i.interval = o.get<std::size_t>("migration_interval").value_or(i.interval);
  i.migrants = o.get<std::size_t>("migrants").value_or(i.migrants);
  i.topology = optim::topology_from_name(o.get<std::string>("topology").value_or("ring"));
  i.topology_seed = o.get<std::uint64_t>("topology_seed").value_or(0);
  i.asynchronous = o.get<bool>("asynchronous").value_or(false);
  if (i.islands == 0) return std::nullopt;
  return i;
}

// The algorithm's options from the dict: the name read by optim::solver_from_name (as `hula optimise
// --algorithm` and a server job read it), its defaults overridden by the dict's members.
optim::SolverOptions solver_options(const std::string& algorithm, Options& o, const optim::RunSettings& settings) {
  optim::SolverOptions named = optim::solver_from_name(algorithm);
  const std::size_t population = o.get<std::size_t>("population").value_or(100);
  if (auto* a = std::get_if<optim::RealGaOptions>(&named)) {
    a->population = population;
    a->crossover_probability = o.get<double>("crossover_probability").value_or(a->crossover_probability);
    a->crossover_eta = o.get<double>("crossover_eta").value_or(a->crossover_eta);
    a->mutation_probability = o.get<double>("mutation_probability");
    a->mutation_eta = o.get<double>("mutation_eta").value_or(a->mutation_eta);
    a->tournament_size = o.get<std::size_t>("tournament_size").value_or(a->tournament_size);
    a->elites = o.get<std::size_t>("elites").value_or(a->elites);
    a->run = settings;
    return named;
  }
  if (auto* a = std::get_if<optim::BinaryGaOptions>(&named)) {
    a->population = population;
    a->crossover_probability = o.get<double>("crossover_probability").value_or(a->crossover_probability);
    a->mutation_probability = o.get<double>("mutation_probability").value_or(a->mutation_probability);
    a->boost_start = o.get<double>("boost_start").value_or(a->boost_start);
    a->boost_end = o.get<double>("boost_end").value_or(a->boost_end);
    a->elites = o.get<std::size_t>("elites").value_or(a->elites);
    a->tournament_size = o.get<std::size_t>("tournament_size").value_or(a->tournament_size);
    const auto selection = o.get<std::string>("selection").value_or("roulette");
    if (selection != "roulette" && selection != "tournament") {
      throw Error(Errc::InvalidOption, "selection = \"" + selection + "\" (expected \"roulette\" or \"tournament\")",
                  {.field = "selection"});
    }
    a->selection = selection == "roulette" ? optim::Selection::Roulette : optim::Selection::Tournament;
    const auto crossover = o.get<std::string>("crossover").value_or("single-point");
    if (crossover != "single-point" && crossover != "uniform") {
      throw Error(Errc::InvalidOption, "crossover = \"" + crossover + "\" (expected \"single-point\" or \"uniform\")",
                  {.field = "crossover"});
    }
    a->crossover = crossover == "uniform" ? optim::BinaryCrossover::Uniform : optim::BinaryCrossover::SinglePoint;
    a->run = settings;
    return named;
  }
  if (auto* a = std::get_if<optim::Nsga2Options>(&named)) {
    a->population = population;
    a->crossover_probability = o.get<double>("crossover_probability").value_or(a->crossover_probability);
    a->crossover_eta = o.get<double>("crossover_eta").value_or(a->crossover_eta);
    a->mutation_probability = o.get<double>("mutation_probability");
    a->mutation_eta = o.get<double>("mutation_eta").value_or(a->mutation_eta);
    a->run = settings;
    return named;
  }
  throw Error(Errc::InvalidArgument,
              "algorithm = \"" + algorithm +
                  "\" is not an algorithm the binding runs (expected \"ga-real\", \"ga-binary\", \"nsga2\", "
                  "\"nelder-mead\" or \"pagmo-<name>\")",
              {.field = "algorithm"});
}

// Nelder–Mead's options: the simplex settings, the evaluation budget and wall time.
optim::NelderMeadOptions nelder_mead_options(Options& o) {
  optim::NelderMeadOptions a;
  a.initial_step = o.get<double>("initial_step").value_or(a.initial_step);
  a.x_tolerance = o.get<double>("x_tolerance").value_or(a.x_tolerance);
  a.f_tolerance = o.get<double>("f_tolerance").value_or(a.f_tolerance);
  a.max_evaluations = o.get<std::size_t>("max_evaluations").value_or(a.max_evaluations);
  a.restarts = o.get<std::size_t>("restarts").value_or(a.restarts);
  a.wall_time_seconds = o.get<double>("wall_time").value_or(a.wall_time_seconds);
  return a;
}

// The run report as `hula optimise` prints it under "report" (io::run_report_to_json with the same identity).
py::object report_object(const optim::RunReport& r, const optim::Problem& problem, const std::string& algorithm,
                         std::uint64_t seed, std::size_t threads) {
  return to_python(
      io::run_report_to_json(r, {.seed = seed, .threads = threads, .algorithm = algorithm, .problem = problem.name}));
}

// A generation's best: the smallest feasible objective (one objective, NaN if none), else each objective's
// smallest value among the feasible, successful individuals (NaN where none).
py::object generation_best(const optim::GenerationLog& g) {
  if (g.objectives == 1) return py::float_(optim::statistics(g).best);
  std::vector<double> best(g.objectives, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (g.failed[i] != 0 || !(g.violation[i] == 0.0)) continue;
    for (std::size_t j = 0; j < g.objectives; ++j) {
      const double v = g.objective_values[i * g.objectives + j];
      if (std::isfinite(v) && !(v >= best[j])) best[j] = v;
    }
  }
  return to_array(best);
}

py::dict run(const optim::Problem& problem, const std::string& algorithm, const py::dict& options,
             const py::object& progress, std::optional<std::vector<double>> reference) {
  Options o(options);
  if (const auto given = o.get<std::vector<double>>("reference")) {
    if (given->size() != problem.objectives)
      throw Error(Errc::InvalidOption,
                  "reference has " + std::to_string(given->size()) + " values for " +
                      std::to_string(problem.objectives) + " objectives",
                  {.field = "reference"});
    reference = given;
  }
  Interruptible job;
  optim::SolveOptions solve;
  std::uint64_t seed = 0;
  std::size_t threads = 1;
  std::vector<double> best_per_generation, mean_per_generation;
  // The convergence graph of a single population, and the progress callback (every algorithm reports its
  // generations: Nelder–Mead its simplex iterations, pagmo's per population of evaluations); islands
  // report per-island statistics instead.
  const optim::GenerationCallback on_generation = [&](const optim::GenerationLog& g) {
    const optim::GenerationStatistics s = optim::statistics(g);
    best_per_generation.push_back(s.best);
    mean_per_generation.push_back(s.mean);
    if (progress.is_none()) return;
    const py::gil_scoped_acquire gil;
    if (py::bool_(progress(g.generation, generation_best(g), g.evaluations))) job.stop();
  };
  if (algorithm.starts_with("pagmo-")) {
    // pagmo's algorithms through the reader `hula optimise --algorithm pagmo-<name>` uses: population,
    // generations, seed and wall_time; Ctrl-C and a True return stop them before their next evaluation.
    io::SolverRequest q;
    q.algorithm = algorithm;
    q.population = o.get<std::size_t>("population");
    q.generations = o.get<std::size_t>("generations");
    q.seed = o.get<std::uint64_t>("seed");
    q.time = o.get<double>("wall_time");
    q.cancel = job.token();
    q.on_generation = on_generation;
    seed = q.seed.value_or(0);
    solve.algorithm = io::solver_options(q);
  } else if (algorithm == "nelder-mead") {
    optim::NelderMeadOptions nm = nelder_mead_options(o);
    nm.cancel = job.token();
    nm.on_generation = on_generation;
    solve.algorithm = nm;
    if (const auto start = o.get<std::vector<double>>("start")) solve.start = *start;
  } else {
    optim::RunSettings settings = run_settings(o);
    settings.stop.cancel = job.token();
    seed = settings.seed;
    threads = settings.threads;
    solve.islands = island_options(o);
    if (!solve.islands)
      settings.on_generation = on_generation;
    else if (!progress.is_none())
      throw Error(Errc::InvalidOption, "callback and verbose are not supported with islands", {.field = "callback"});
    solve.algorithm = solver_options(algorithm, o, settings);
  }
  o.check_all_used(algorithm);
  const optim::SolveResult r = job.run([&] { return optim::solve(problem, solve); });
  py::dict out;
  if (!job.interrupt().is_none()) out["interrupt"] = job.interrupt();
  const bool front = problem.objectives > 1 || std::holds_alternative<optim::Nsga2Options>(solve.algorithm);
  if (!front) {
    const optim::Solution& best = r.solutions.front();
    out["x"] = to_array(best.variables);
    out["f"] = to_array(best.objectives);
    out["violation"] = best.violation;
  } else {
    out["front_x"] = rows(r.solutions, true, problem.dimension());
    out["front_f"] = rows(r.solutions, false, problem.objectives);
    if (reference) {
      out["hypervolume"] = io::feasible_hypervolume(r.solutions, problem.objectives, *reference);
      out["reference"] = to_array(*reference);
    }
  }
  if (!r.population.empty()) {
    out["population_x"] = rows(r.population, true, problem.dimension());
    out["population_f"] = rows(r.population, false, problem.objectives);
  }
  out["report"] = report_object(r.report, problem, algorithm, seed, threads);
  if (solve.islands) {
    py::list per;
    for (const optim::IslandReport& i : r.islands) {
      py::dict d;
      d["island"] = i.island;
      d["seed"] = i.seed;
      if (problem.objectives == 1) {
        d["x"] = to_array(i.best.variables);
        d["f"] = to_array(i.best.objectives);
      }
      d["report"] = to_python(io::run_report_to_json(i.report));
      d["sent"] = i.sent;
      d["received"] = i.received;
      d["accepted"] = i.accepted;
      if (problem.objectives > 1) d["archive"] = i.archive.size();
      py::list events;
      for (const optim::MigrationEvent& e : i.migrations)
        events.append(py::dict(py::arg("generation") = e.generation, py::arg("from") = e.from,
                               py::arg("received") = e.received, py::arg("accepted") = e.accepted));
      d["migrations"] = events;
      per.append(d);
    }
    out["islands"] = per;
    return out;
  }
  out["best_per_generation"] = to_array(best_per_generation);
  out["mean_per_generation"] = to_array(mean_per_generation);
  return out;
}

// The batch evaluation of a Python callable: copies the points into a fresh (n, d) array (the
// callable may keep it), calls it under the GIL and copies its (n, k) or, for k = 1, (n,) result.
optim::BatchEvaluateFn python_batch(py::function fn, std::size_t d, std::size_t k) {
  return [fn = std::move(fn), d, k](std::span<const double> points, std::span<double> values) {
    const py::gil_scoped_acquire acquire;
    const std::size_t n = points.size() / d;
    Doubles x({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(d)});
    std::copy(points.begin(), points.end(), x.mutable_data());
    const py::object result = fn(x);
    const Doubles f = as_doubles(result, "objective result");
    const bool ok =
        (f.ndim() == 2 && static_cast<std::size_t>(f.shape(0)) == n && static_cast<std::size_t>(f.shape(1)) == k) ||
        (k == 1 && f.ndim() == 1 && static_cast<std::size_t>(f.shape(0)) == n);
    if (!ok) {
      throw Error(Errc::InvalidArgument,
                  "the objective returned shape " + shape_text(f) + " for a batch of " + std::to_string(n) +
                      " points: expected (" + std::to_string(n) + ", " + std::to_string(k) + ")" +
                      (k == 1 ? " or (" + std::to_string(n) + ",)" : ""),
                  {.field = "objective"});
    }
    std::copy_n(f.data(), n * k, values.begin());
  };
}

}  // namespace

void register_optimise(py::module_& m) {
  m.def(
      "optimise_callable",
      [](py::function fn, py::handle lower, py::handle upper, std::size_t objectives, std::size_t inequality,
         std::size_t equality, py::handle precision, const std::string& name, const std::string& algorithm,
         const py::dict& options, const py::object& progress) {
        const std::vector<double> lo = as_vector(lower, "lower");
        const std::vector<double> hi = as_vector(upper, "upper");
        if (lo.size() != hi.size()) {
          throw Error(Errc::InvalidArgument,
                      "lower has " + std::to_string(lo.size()) + " bounds but upper has " + std::to_string(hi.size()),
                      {.field = "upper"});
        }
        std::vector<double> prec(lo.size(), 0.0);
        if (!precision.is_none()) {
          const std::vector<double> p = as_vector(precision, "precision");
          if (p.size() == 1)
            prec.assign(lo.size(), p[0]);
          else if (p.size() == lo.size())
            prec = p;
          else
            throw Error(Errc::InvalidArgument, "precision must be one number or one per variable",
                        {.field = "precision"});
        }
        optim::Problem p;
        p.name = name;
        for (std::size_t i = 0; i < lo.size(); ++i)
          p.variables.push_back({"x" + std::to_string(i), lo[i], hi[i], prec[i]});
        p.objectives = objectives;
        p.inequality_constraints = inequality;
        p.equality_constraints = equality;
        p.evaluate_many = python_batch(std::move(fn), lo.size(), p.values_per_point());
        return run(p, algorithm, options, progress, std::nullopt);
      },
      py::arg("objective"), py::arg("lower"), py::arg("upper"), py::arg("objectives"), py::arg("inequality"),
      py::arg("equality"), py::arg("precision"), py::arg("name"), py::arg("algorithm"), py::arg("options"),
      py::arg("progress") = py::none());

  m.def(
      "optimise_builtin",
      [](const std::string& name, std::size_t dimension, std::size_t objectives, py::handle precision,
         const std::string& algorithm, const py::dict& options, const py::object& progress) {
        auto [p, reference] = io::builtin_problem(name, dimension, objectives);
        if (!precision.is_none()) {
          const auto q = precision.cast<double>();
          for (optim::Variable& v : p.variables) v.precision = q;
        }
        return run(p, algorithm, options, progress, std::move(reference));
      },
      py::arg("name"), py::arg("dimension"), py::arg("objectives"), py::arg("precision"), py::arg("algorithm"),
      py::arg("options"), py::arg("progress") = py::none());

  m.def(
      "evaluate_builtin",
      [](const std::string& name, std::size_t dimension, std::size_t objectives, py::handle points) {
        const optim::Problem p = optim::test_problem(name, dimension, objectives);
        const Doubles x = as_doubles(points, "points");
        const std::size_t d = p.dimension();
        if (x.ndim() != 2 || static_cast<std::size_t>(x.shape(1)) != d) {
          throw Error(Errc::InvalidArgument,
                      "points has shape " + shape_text(x) + ": expected (n, " + std::to_string(d) + ")",
                      {.field = "points"});
        }
        const auto n = static_cast<std::size_t>(x.shape(0));
        const std::size_t k = p.values_per_point();
        Doubles values({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(k)});
        std::vector<std::uint8_t> failed(n);
        const py::gil_scoped_release release;
        (void)optim::evaluate_batch(p, std::span<const double>(x.data(), n * d),
                                    std::span<double>(values.mutable_data(), n * k), failed);
        return values;
      },
      py::arg("name"), py::arg("dimension"), py::arg("objectives"), py::arg("points"));

  m.def(
      "builtin_problem",
      [](const std::string& name, std::size_t dimension, std::size_t objectives) {
        const optim::Problem p = optim::test_problem(name, dimension, objectives);
        std::vector<double> lo, hi;
        for (const optim::Variable& v : p.variables) {
          lo.push_back(v.lower);
          hi.push_back(v.upper);
        }
        py::dict d;
        d["name"] = p.name;
        d["lower"] = to_array(lo);
        d["upper"] = to_array(hi);
        d["objectives"] = p.objectives;
        d["inequality"] = p.inequality_constraints;
        d["equality"] = p.equality_constraints;
        return d;
      },
      py::arg("name"), py::arg("dimension") = 0, py::arg("objectives") = 0);
}

}  // namespace hula::python
