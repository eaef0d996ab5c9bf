# SPDX-License-Identifier: MIT
"""Python binding overheads (docs/benchmarks.md "Python"):

1. curve(t) on 1e6 parameters, with a fresh output array and with out=, against
   the C++ batch evaluation alone timed inside the module (same build, same
   curve, same t, same output buffer);
2. optimise() on sphere-30, population 256, with a vectorised NumPy objective,
   against the built-in C++ sphere: evaluations per second of the whole run.

    PYTHONPATH=build/ci/python /usr/bin/python3 python/bench/bench_python.py
"""
import time

import numpy as np

import hulahoops as hh
from hulahoops import _core


def best_of(f, repeats):
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        f()
        best = min(best, time.perf_counter() - start)
    return best


def main():
    rng = np.random.default_rng(1)
    curve = hh.interpolate(rng.uniform(0, 100, (50, 3)))
    t = rng.uniform(0, 1, 1_000_000)
    out = np.empty((t.size, 3))
    curve(t, out=out)  # warm the span cache and the pages of out
    cpp = _core._time_batch_evaluate(curve, t, out, 15)
    py_out = best_of(lambda: curve(t, out=out), 15)
    py_new = best_of(lambda: curve(t), 15)
    print("curve(t), 1e6 parameters, cubic with 47 spans")
    print(f"  C++ batch alone         {cpp * 1e3:8.2f} ms")
    print(f"  curve(t, out=out)       {py_out * 1e3:8.2f} ms  ({py_out / cpp - 1:+.1%})")
    print(f"  curve(t) (new array)    {py_new * 1e3:8.2f} ms  ({py_new / cpp - 1:+.1%})")

    d, n, g = 30, 256, 200
    lower, upper = np.full(d, -5.12), np.full(d, 5.12)
    problem = hh.Problem(lambda X: np.einsum("ij,ij->i", X, X), lower, upper)

    def rate(run):
        return run.report["evaluations"] / run.report["seconds"]

    cpp_rates = [rate(hh.optimise("sphere", "ga-real", dimension=d, population=n, generations=g, seed=s))
                 for s in range(5)]
    py_rates = [rate(hh.optimise(problem, "ga-real", population=n, generations=g, seed=s)) for s in range(5)]
    c, p = max(cpp_rates), max(py_rates)
    print(f"optimise, sphere-{d}, population {n}, {g} generations (best of 5)")
    print(f"  C++ objective           {c:12.0f} evaluations/s")
    print(f"  NumPy objective         {p:12.0f} evaluations/s  ({p / c:.0%} of C++)")


if __name__ == "__main__":
    main()
