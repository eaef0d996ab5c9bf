# SPDX-License-Identifier: MIT
# callback= and verbose= on optimise and the studies: the callback sees every
# generation of real runs with the values the result reports, a true return
# stops the run with its best so far, verbose prints one line per generation.
import json
import re
import time

import numpy as np
import pytest

import hulahoops as hh
from conftest import SOURCE

STUDIES = SOURCE / "examples" / "studies"


def test_callback_sees_every_generation_with_the_reported_best():
    # checks the callback runs for generations 0..G in order with the result's best_per_generation, and
    # evaluations growing by one population per generation
    calls = []
    r = hh.optimise("rastrigin", dimension=4, population=30, generations=20, seed=7,
                    callback=lambda g, best, ev: calls.append((g, best, ev)))
    assert [c[0] for c in calls] == list(range(21))
    assert np.array_equal([c[1] for c in calls], r.best_per_generation)
    assert [c[2] for c in calls] == [30 * (g + 1) for g in range(21)]
    assert r.report["evaluations"] == calls[-1][2]


def test_callback_returning_true_stops_with_the_best_so_far():
    # checks True at generation 5 ends the run there (termination Cancelled, 5 generations), with the same
    # generations as an uninterrupted run of the same seed up to that point
    full = hh.optimise("sphere", dimension=3, population=20, generations=30, seed=4)
    r = hh.optimise("sphere", dimension=3, population=20, generations=30, seed=4, callback=lambda g, b, e: g == 5)
    assert r.report["termination"] == "Cancelled"
    assert r.report["generations"] == 5
    assert np.array_equal(r.best_per_generation, full.best_per_generation[:6])
    assert r.f[0] == r.best_per_generation[-1]


def test_callback_with_a_python_objective_and_constraints():
    # checks a Python objective with one inequality constraint: best is the smallest feasible objective
    # (x0 + x1 >= 1 cuts off the unconstrained minimum at 0; the optimum is 0.5 at x = (0.5, 0.5))
    def objective(X):
        return np.column_stack([np.sum(X * X, axis=1), 1 - X[:, 0] - X[:, 1]])

    bests = []
    r = hh.optimise(hh.Problem(objective, [-2, -2], [2, 2], inequality=1), population=40, generations=60, seed=1,
                    callback=lambda g, b, e: bests.append(b))
    assert np.array_equal(bests, r.best_per_generation)
    assert all(b >= 0.5 - 1e-12 for b in bests if np.isfinite(b))
    assert bests[-1] == pytest.approx(0.5, abs=1e-2)


def test_nsga2_callback_gets_each_objectives_minimum():
    # checks NSGA-II's best is an array of each objective's smallest value, equal at the last generation to
    # the final population's column minima (ZDT1 has no constraints: all feasible)
    seen = []
    r = hh.optimise("zdt1", "nsga2", dimension=6, population=24, generations=15, seed=3,
                    callback=lambda g, b, e: seen.append(np.array(b)))
    assert len(seen) == 16 and all(b.shape == (2,) for b in seen)
    assert np.array_equal(seen[-1], r.population_f.min(axis=0))


def test_callback_exception_propagates():
    # checks an exception raised by the callback ends the run and reaches the caller unchanged
    class Stop(Exception):
        pass

    def callback(g, b, e):
        if g == 3:
            raise Stop("from the callback")

    with pytest.raises(Stop, match="from the callback"):
        hh.optimise("sphere", dimension=2, population=10, generations=50, callback=callback)


def test_callback_refused_with_islands():
    # checks island runs refuse callback and verbose (InvalidOptionError naming callback) rather than ignore them
    with pytest.raises(hh.InvalidOptionError) as e:
        hh.optimise("sphere", dimension=2, islands=2, generations=3, callback=lambda *a: None)
    assert e.value.where["field"] == "callback"
    with pytest.raises(hh.InvalidOptionError):
        hh.optimise("sphere", dimension=2, islands=2, generations=3, verbose=True)


def test_nelder_mead_callback_sees_every_simplex_and_stops():
    # checks Nelder-Mead calls back once per simplex iteration and once with the final simplex (generations
    # 0..G, G the report's), best the simplex's lowest value (the result's f at the end), evaluations growing;
    # the result is the same without the callback; True at generation 5 ends the run after that iteration
    # (Cancelled, 6 iterations), its final simplex reported as generation 6
    calls = []
    r = hh.optimise("rosenbrock", "nelder-mead", dimension=3, max_evaluations=3000,
                    callback=lambda g, best, ev: calls.append((g, best, ev)))
    plain = hh.optimise("rosenbrock", "nelder-mead", dimension=3, max_evaluations=3000)
    assert np.array_equal(r.x, plain.x) and np.array_equal(r.f, plain.f)
    assert r.report["evaluations"] == plain.report["evaluations"]
    assert [c[0] for c in calls] == list(range(r.report["generations"] + 1))
    assert np.array_equal([c[1] for c in calls], r.best_per_generation)
    assert [c[2] for c in calls] == sorted(c[2] for c in calls) and calls[-1][2] == r.report["evaluations"]
    assert calls[-1][1] == r.f[0]
    stopped = hh.optimise("rosenbrock", "nelder-mead", dimension=3, max_evaluations=3000,
                          callback=lambda g, b, e: g == 5)
    assert stopped.report["termination"] == "Cancelled" and stopped.report["generations"] == 6
    assert np.array_equal(stopped.best_per_generation[:6], r.best_per_generation[:6])
    assert stopped.f[0] == stopped.best_per_generation[6] <= calls[5][1]


def test_pagmo_callback_counts_generations_by_evaluations():
    # checks pagmo's DE calls back for generations 0..G with one population of evaluations each, the last
    # being the final population (its best the result's f), and gives the same result without the callback
    calls = []
    r = hh.optimise("sphere", "pagmo-de", dimension=4, population=20, generations=12, seed=2,
                    callback=lambda g, best, ev: calls.append((g, best, ev)))
    plain = hh.optimise("sphere", "pagmo-de", dimension=4, population=20, generations=12, seed=2)
    assert np.array_equal(r.x, plain.x) and np.array_equal(r.f, plain.f)
    assert [c[0] for c in calls] == list(range(13))
    assert [c[2] for c in calls] == [20 * (g + 1) for g in range(13)] and calls[-1][2] == r.report["evaluations"]
    assert calls[-1][1] == r.f[0]


def test_pagmo_callback_true_stops_the_run_with_the_best_so_far():
    # checks a True return at generation 5 stops a pagmo DE run of a billion generations on a Python objective
    # (Cancelled, 5 generations, 121 evaluations: the one that handed generation 5 over is the last made)
    # within 0.5 s of the return, with a best whose value is the objective at its x and no worse than any
    # generation's; and that a callback that never stops, with a wall time never reached, gives the plain
    # run's result bit for bit
    def objective(X):
        return np.sum((X - 0.25) ** 2, axis=1)

    problem = hh.Problem(objective, -np.ones(4), np.ones(4))
    returned = []

    def stop_at_five(g, best, ev):
        if g == 5:
            returned.append(time.monotonic())
            return True
        return False

    r = hh.optimise(problem, "pagmo-de", population=20, generations=10**9, seed=3, callback=stop_at_five)
    ended = time.monotonic()
    assert ended - returned[0] < 0.5, ended - returned[0]
    assert r.report["termination"] == "Cancelled" and r.report["generations"] == 5
    assert r.report["evaluations"] == 121
    assert r.f[0] == objective(r.x.reshape(1, -1))[0]
    assert len(r.best_per_generation) == 6 and r.f[0] <= np.min(r.best_per_generation)
    plain = hh.optimise(problem, "pagmo-de", population=20, generations=30, seed=3)
    watched = hh.optimise(problem, "pagmo-de", population=20, generations=30, seed=3, wall_time=1e6,
                          callback=lambda g, best, ev: False)
    assert np.array_equal(plain.x, watched.x) and np.array_equal(plain.f, watched.f)
    assert plain.report["evaluations"] == watched.report["evaluations"] == 20 * 31
    assert watched.report["termination"] == plain.report["termination"] == "MaxGenerations"


def test_fit_callback_follows_the_search():
    # checks fit calls back once per candidate curve (generations 0, 1, ... in order, solves growing) and
    # last with the result's largest deviation and solves, and fits the same curve without the callback
    rng = np.random.default_rng(5)
    x = np.linspace(0, 100, 80)
    pts = np.column_stack([x, 10 * np.sin(x / 15) + rng.normal(0, 0.05, x.size)])
    setup = {"format": "hula-study", "version": 1, "study": "fit", "points": pts.tolist(), "class": "A"}
    calls = []
    r = hh.fit(setup, callback=lambda g, best, ev: calls.append((g, best, ev)))
    plain = hh.fit(setup)
    assert np.array_equal(r.curve.control_points, plain.curve.control_points)
    assert np.array_equal(r.curve.knots, plain.curve.knots)
    assert len(calls) > 2 and [c[0] for c in calls] == list(range(len(calls)))
    assert [c[2] for c in calls] == sorted(c[2] for c in calls)
    assert calls[-1][1] == r.after.max_deviation and calls[-1][2] == r.fits
    assert all(c[1] > 0 for c in calls)


def test_verbose_prints_one_line_per_generation(capsys):
    # checks verbose writes generation, evaluations and best to stderr, the last line's best being f
    r = hh.optimise("sphere", dimension=2, population=10, generations=8, seed=2, verbose=True)
    lines = capsys.readouterr().err.strip().splitlines()
    assert len(lines) == 9
    m = re.fullmatch(r"optimise: generation (\d+), evaluations (\d+), best (\S+)", lines[-1])
    assert m and int(m[1]) == 8 and int(m[2]) == 90
    assert float(m[3]) == pytest.approx(r.f[0], rel=1e-5)


def test_study_callback_and_stop():
    # checks match-curvature's GA (thesis 8.2.1 example 1: 50 generations) calls back 51 times with
    # evaluations growing, and a True return at generation 10 stops it there (termination Cancelled) with
    # best points inside their offsets that fit the target better than the start
    setup = json.loads((STUDIES / "match-curvature-example1.json").read_text())
    calls = []
    hh.match_curvature(setup, callback=lambda g, b, e: calls.append((g, b, e)))
    assert [c[0] for c in calls] == list(range(51))
    assert all(a[2] < b[2] for a, b in zip(calls, calls[1:]))
    stopped = hh.match_curvature(setup, callback=lambda g, b, e: g == 10)
    assert stopped.ga.termination == "Cancelled" and stopped.ga.generations == 10
    assert stopped.evaluations == calls[10][2]  # 11 generations of 50
    # the free point within its offsets (x 5 - 30 ... 5 + 35, y 20 +- 30; the binary grid's step 0.001 over)
    p = np.asarray(stopped.best_points)
    assert -25 - 1e-3 <= p[1][0] <= 40 + 1e-3 and -10 - 1e-3 <= p[1][1] <= 50 + 1e-3
    assert stopped.after.mean < stopped.before.mean


def test_fair_knots_verbose(capsys):
    # checks fair-knots prints progress lines labelled with the study for its GA (thesis 7.4 example 1)
    setup = json.loads((STUDIES / "fair-knots-7.4-example1.json").read_text())
    setup["method"] = "ga"
    hh.fair_knots(setup, verbose=True)
    lines = capsys.readouterr().err.strip().splitlines()
    assert lines and all(line.startswith("fair-knots: generation ") for line in lines)


def test_fair_knots_ga_and_deterministic_report_the_same_quantity():
    # checks the fair-knots GA calls back with its generations' best energies E, as the deterministic
    # optimiser does (not the GA's own E / E_start): on thesis 7.3 example 2, the running minimum of the GA's
    # bests (and the start's energy) is its convergence graph, their overall minimum the GA's energy, and
    # both optimisers' last bests agree with their energies to 1e-12 relative
    setup = json.loads((STUDIES / "fair-knots-7.3-example2.json").read_text())
    setup.pop("map", None)
    setup["method"] = "ga"
    setup["ga"] = {"algorithm": "real", "population": 20, "generations": 10}
    ga_calls = []
    ga = hh.fair_knots(setup, callback=lambda g, b, e: ga_calls.append(b))
    running = np.minimum.accumulate(np.minimum(ga.chord_length.energy, ga_calls))
    assert np.array_equal(running, ga.ga.convergence)
    assert ga.ga.energy < ga.chord_length.energy
    assert min(ga_calls) == pytest.approx(ga.ga.energy, rel=1e-12)
    setup["method"] = "deterministic"
    nm_calls = []
    nm = hh.fair_knots(setup, callback=lambda g, b, e: nm_calls.append(b))
    assert nm_calls[-1] == pytest.approx(nm.deterministic.energy, rel=1e-12)
    assert nm_calls[-1] == pytest.approx(min(ga_calls), rel=0.05)  # one optimum, two ways: one unit


def test_fair_knots_deterministic_callback_and_stop():
    # checks a deterministic fair-knots study (thesis 7.3 example 2, Nelder-Mead only) calls back with its
    # simplex iterations as generations 0, 1, 2, ... in energy units: the last best is the result's energy,
    # the evaluations are the result's less the start's energy, the result is the one of an unwatched run;
    # a True return at generation 5 stops it there (termination Cancelled) no worse than chord length
    setup = json.loads((STUDIES / "fair-knots-7.3-example2.json").read_text())
    setup["method"] = "deterministic"
    setup.pop("map", None)
    calls = []
    r = hh.fair_knots(setup, callback=lambda g, b, e: calls.append((g, b, e)))
    assert len(calls) > 10 and [c[0] for c in calls] == list(range(len(calls)))
    assert all(a[1] >= b[1] and a[2] <= b[2] for a, b in zip(calls, calls[1:]))
    assert calls[-1][1] == pytest.approx(r.deterministic.energy, rel=1e-14)
    assert calls[-1][2] + 1 == r.deterministic.evaluations
    plain = hh.fair_knots(setup)
    assert plain.deterministic.energy == r.deterministic.energy
    assert np.array_equal(plain.deterministic.parameters, r.deterministic.parameters)
    stopped = hh.fair_knots(setup, callback=lambda g, b, e: g == 5)
    assert stopped.deterministic.termination == "Cancelled"
    assert len(stopped.deterministic.convergence) == 6
    assert r.deterministic.energy < stopped.deterministic.energy <= stopped.chord_length.energy
