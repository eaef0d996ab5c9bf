# SPDX-License-Identifier: MIT
# optimise(): Python batch objectives against the C++ built-in problems (the
# same run bit for bit), pygmo-style problems unchanged, exceptions that
# propagate with their traceback and stop the run, options refused by name.
import traceback

import numpy as np
import pytest

import hulahoops as hh
from conftest import hula


def builtin_as_python(name, d, m=0):
    """A hulahoops.Problem evaluating the C++ built-in problem from Python (same arithmetic)."""
    info = hh.builtin_problem(name, d, m)
    return hh.Problem(lambda X: hh.evaluate_builtin(name, X, d, m), info["lower"], info["upper"],
                      objectives=info["objectives"])


@pytest.mark.parametrize("algorithm", ["ga-real", "ga-binary"])
def test_python_objective_repeats_the_cpp_run_bit_for_bit(algorithm):
    # checks a run with the objective called from Python equals the all-C++ run with the same seed, bit for bit
    opts = dict(population=40, generations=30, seed=7, precision=1e-4)
    cpp = hh.optimise("rastrigin", algorithm, dimension=5, **opts)
    py = hh.optimise(builtin_as_python("rastrigin", 5), algorithm, **opts)
    assert np.array_equal(cpp.x, py.x) and np.array_equal(cpp.f, py.f)
    assert np.array_equal(cpp.best_per_generation, py.best_per_generation)
    assert cpp.report["evaluations"] == py.report["evaluations"] == 40 * 31


def test_nsga2_front_repeats_the_cpp_run_bit_for_bit():
    # checks NSGA-II on ZDT1 through Python equals the C++ built-in run, front and population
    cpp = hh.optimise("zdt1", "nsga2", dimension=10, population=40, generations=20, seed=3)
    py = hh.optimise(builtin_as_python("zdt1", 10), "nsga2", population=40, generations=20, seed=3)
    assert np.array_equal(cpp.front_f, py.front_f) and np.array_equal(cpp.front_x, py.front_x)
    assert cpp.front_f.shape[1] == 2


def test_nsga2_islands_merge_archives_into_a_bounded_front():
    # checks NSGA-II islands against their definition: a mutually non-dominated front of at most
    # islands x population points, per-island archives of at most as many, and exact repetition
    opts = dict(dimension=10, population=20, generations=30, seed=2, islands=4)
    a = hh.optimise("zdt1", "nsga2", **opts)
    b = hh.optimise("zdt1", "nsga2", **opts)
    assert np.array_equal(a.front_f, b.front_f) and np.array_equal(a.front_x, b.front_x)
    f = a.front_f
    assert 0 < len(f) <= 4 * 20
    dominated = (f[:, None, :] <= f[None, :, :]).all(axis=2) & (f[:, None, :] < f[None, :, :]).any(axis=2)
    assert not dominated.any()
    assert all(0 < isl["archive"] <= 4 * 20 for isl in a.islands)


def test_vectorised_numpy_sphere_converges():
    # checks a NumPy sphere objective reaches the known minimum 0 at the origin within 1e-3
    calls = []

    def sphere(X):
        calls.append(X.shape)
        return np.sum(X * X, axis=1)

    r = hh.optimise(hh.Problem(sphere, -np.ones(4), np.ones(4)), "ga-real", population=40, generations=200, seed=1)
    assert r.f[0] < 1e-6 and np.all(np.abs(r.x) < 1e-3)
    assert calls[0] == (40, 4) and len(calls) == 201  # one call per generation with the whole batch


class ConstrainedUdp:
    """A pygmo UDP: min x0 + x1 s.t. 0.5 - (x0 - x1) <= 0 and 1 - x0 - x1 <= 0 (inequalities, pygmo's g <= 0).
    The optimum value is 1, on the segment x0 + x1 = 1 with x0 >= 0.75."""

    def fitness(self, x):
        return [x[0] + x[1], 0.5 - (x[0] - x[1]), 1 - x[0] - x[1]]

    def get_bounds(self):
        return [0, 0], [2, 2]

    def get_nic(self):
        return 2


def test_pygmo_udp_unchanged():
    # checks a pygmo-style UDP (per-point fitness, inequality constraints) solves to the analytic optimum 1
    r = hh.optimise(ConstrainedUdp(), "ga-real", population=60, generations=300, seed=2)
    assert r.f[0] == pytest.approx(1.0, abs=1e-3)
    assert r.violation == 0.0
    assert r.x[0] - r.x[1] >= 0.5 and r.x[0] + r.x[1] >= 1.0


def test_problem_is_a_pygmo_udp():
    # checks hulahoops.Problem exposes pygmo's interface with pygmo's constraint order
    p = hh.Problem(lambda X: np.stack([X[:, 0], X[:, 1] - 1, X[:, 0] - 2], axis=1), [0, 0], [3, 3],
                   inequality=1, equality=1)
    assert p.get_nobj() == 1 and p.get_nic() == 1 and p.get_nec() == 1
    lo, hi = p.get_bounds()
    assert np.array_equal(lo, [0, 0]) and np.array_equal(hi, [3, 3])
    # Flexo order (f, g, h) = (1, 1, -1) becomes pygmo's (f, h, g) = (1, -1, 1)
    assert np.array_equal(p.fitness([1.0, 2.0]), [1.0, -1.0, 1.0])
    assert np.array_equal(p.batch_fitness([1.0, 2.0, 0.0, 0.0]), [1.0, -1.0, 1.0, 0.0, -2.0, -1.0])


def test_raising_objective_propagates_with_traceback_and_stops():
    # checks the objective's own exception reaches the caller with its frame in the traceback, and no call follows
    calls = []

    def objective(X):
        calls.append(1)
        if len(calls) == 3:
            raise KeyError("boom in generation 2")
        return np.sum(X * X, axis=1)

    with pytest.raises(KeyError, match="boom") as e:
        hh.optimise(hh.Problem(objective, -np.ones(3), np.ones(3)), "ga-real", population=10, generations=50)
    frames = [f.name for f in traceback.extract_tb(e.value.__traceback__)]
    assert "objective" in frames
    assert len(calls) == 3
    # the interpreter and the module are in a clean state: the next run works
    r = hh.optimise(hh.Problem(lambda X: np.sum(X * X, axis=1), -np.ones(3), np.ones(3)), population=10,
                    generations=3)
    assert r.report["termination"] == "MaxGenerations"


def test_bad_results_and_options_are_refused_by_name():
    # checks a wrongly shaped objective result names the shape, and an unknown option names the option
    p = hh.Problem(lambda X: np.zeros((X.shape[0], 2)), [0], [1])
    with pytest.raises(hh.InvalidArgumentError, match=r"returned shape \(10, 2\).*expected \(10, 1\)"):
        hh.optimise(p, population=10, generations=2)
    with pytest.raises(hh.InvalidOptionError) as e:
        hh.optimise("sphere", dimension=3, populaton=10)
    assert e.value.where["field"] == "populaton"
    with pytest.raises(hh.InvalidArgumentError, match="algorithm"):
        hh.optimise("sphere", "simulated-annealing", dimension=3)


def test_nan_rows_are_failed_evaluations():
    # checks NaN objective rows count as failed evaluations and rank last, not as an error
    def f(X):
        v = np.sum(X * X, axis=1)
        v[X[:, 0] > 0.5] = np.nan
        return v

    r = hh.optimise(hh.Problem(f, -np.ones(2), np.ones(2)), population=20, generations=20, seed=4)
    assert r.report["failed_evaluations"] > 0 and np.isfinite(r.f[0]) and r.x[0] <= 0.5


@pytest.mark.parametrize("algorithm,problem,args", [
    ("ga-real", "rastrigin", dict(population=20, generations=15)),
    ("ga-binary", "rastrigin", dict(population=20, generations=15, precision=1e-4)),
    ("nsga2", "zdt1", dict(population=20, generations=10)),
    ("ga-real", "sphere", dict(population=20, generations=12, islands=2, migration_interval=4)),
    ("nelder-mead", "rosenbrock", dict(max_evaluations=300)),
])
def test_report_equals_the_cli_report(algorithm, problem, args):
    # checks Python's run report is the one `hula optimise` prints for the same problem and seed (one writer,
    # io::run_report_to_json): every member equal but the wall time, and the same best point
    flags = {"population": "--population", "generations": "--generations", "precision": "--precision",
             "islands": "--islands", "migration_interval": "--migration-interval",
             "max_evaluations": "--evaluations"}
    cli_args = ["optimise", "--problem", problem, "--dimension", 4, "--algorithm", algorithm]
    if algorithm != "nelder-mead":
        cli_args += ["--seed", 5]
    for key, value in args.items():
        cli_args += [flags[key], value]
    cli = hula(*cli_args)
    options = dict(args)
    precision = options.pop("precision", None)
    if algorithm != "nelder-mead":
        options["seed"] = 5
    py = hh.optimise(problem, algorithm, dimension=4, precision=precision, **options)
    cli_report, py_report = dict(cli["report"]), dict(py.report)
    assert list(py_report) == list(cli_report)
    cli_report.pop("seconds"), py_report.pop("seconds")
    assert py_report == cli_report
    if py.x is not None:
        assert py.x.tolist() == cli["best"]["variables"] and py.f.tolist() == cli["best"]["objectives"]


def test_nelder_mead_terminations():
    # checks Nelder–Mead through optimise reports Converged on sphere-3 (minimum 0 at the origin, reached from
    # (1, 2, 3)) and MaxEvaluations when its budget of 10 evaluations cannot solve Rosenbrock
    done = hh.optimise("sphere", "nelder-mead", dimension=3, start=[1.0, 2.0, 3.0])
    assert done.report["termination"] == "Converged" and np.allclose(done.x, 0.0, atol=1e-6)
    cut = hh.optimise("rosenbrock", "nelder-mead", dimension=2, max_evaluations=10, start=[-1.2, 1.0])
    assert cut.report["termination"] == "MaxEvaluations" and cut.report["evaluations"] <= 12
