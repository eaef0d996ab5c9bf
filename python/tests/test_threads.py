# SPDX-License-Identifier: MIT
# Reference counting and the GIL: the binding keeps no stray references to
# arguments, objectives or results, releases the GIL in its C++ loops (another
# Python thread runs meanwhile) and is safe to call from several threads.
import sys
import threading
import time

import numpy as np

import hulahoops as hh


def test_no_reference_leaks(space_curve):
    # checks refcounts of arguments, results and objectives are unchanged by 100 calls
    t = np.linspace(0, 1, 100)
    before = sys.getrefcount(t), sys.getrefcount(space_curve)
    for _ in range(100):
        p = space_curve(t)
        space_curve.derivatives(t, 2)
        hh.analyse(space_curve, 10)
    assert (sys.getrefcount(t), sys.getrefcount(space_curve)) == before
    assert sys.getrefcount(p) == 2  # the name p and getrefcount's argument

    def objective(X):
        return np.sum(X * X, axis=1)

    problem = hh.Problem(objective, -np.ones(3), np.ones(3))
    ref = sys.getrefcount(objective), sys.getrefcount(problem)
    for _ in range(5):
        hh.optimise(problem, population=10, generations=3)
    assert (sys.getrefcount(objective), sys.getrefcount(problem)) == ref


def test_gil_is_released_during_evaluation(space_curve):
    # checks another Python thread runs while curve(t) is inside C++: its timestamp falls inside one call
    t = np.random.default_rng(0).uniform(0, 1, 2_000_000)
    started = threading.Event()
    calls, stamps = [], []

    def worker():
        started.set()
        while not stamps and len(calls) < 200:
            t0 = time.perf_counter()
            space_curve(t)
            calls.append((t0, time.perf_counter()))

    def watcher():
        started.wait()
        time.sleep(0.001)
        stamps.append(time.perf_counter())  # needs the GIL: only possible inside a call if the call released it

    threads = [threading.Thread(target=worker), threading.Thread(target=watcher)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert any(t0 < stamps[0] < t1 for t0, t1 in calls)


def test_concurrent_calls_agree():
    # checks 8 threads evaluating, analysing and optimising at once give the single-thread results
    curve = hh.interpolate(np.random.default_rng(5).uniform(0, 10, (30, 3)))
    t = np.linspace(0, 1, 20_000)
    expected = curve(t)
    expected_kappa = hh.analyse(curve, 500)["curvature"]
    expected_run = hh.optimise("rastrigin", dimension=4, population=20, generations=10, seed=1).x
    problem = hh.Problem(lambda X: hh.evaluate_builtin("rastrigin", X, 4), -5.12 * np.ones(4), 5.12 * np.ones(4))
    errors = []

    def work(i):
        try:
            for _ in range(5):
                assert np.array_equal(curve(t), expected)
                assert np.array_equal(hh.analyse(curve, 500)["curvature"], expected_kappa, equal_nan=True)
            r = hh.optimise(problem, population=20, generations=10, seed=1)
            assert np.array_equal(r.x, expected_run)
        except BaseException as e:  # noqa: BLE001 - reported to the main thread
            errors.append((i, e))

    threads = [threading.Thread(target=work, args=(i,)) for i in range(8)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert not errors
