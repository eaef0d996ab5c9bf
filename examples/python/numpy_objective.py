# SPDX-License-Identifier: MIT
"""A vectorised NumPy objective with Flexo: one population, then four islands
with the same number of evaluations (Schwefel's function, thesis app. 6 style).

    PYTHONPATH=build/ci/python /usr/bin/python3 examples/python/numpy_objective.py
"""
import os

import numpy as np

import hulahoops as hh

d = 10


def schwefel(X):
    """Schwefel 2.26 shifted to minimum 0 at x_i = 420.9687."""
    return 418.9828872724339 * X.shape[1] - np.sum(X * np.sin(np.sqrt(np.abs(X))), axis=1)


problem = hh.Problem(schwefel, np.full(d, -500.0), np.full(d, 500.0), name="schwefel-10")
generations = 40 if os.environ.get("HULA_EXAMPLE_QUICK") else 200
single = hh.optimise(problem, "ga-real", population=200, generations=generations, seed=1)
islands = hh.optimise(problem, "ga-real", population=50, generations=generations, seed=1, islands=4,
                      migration_interval=10, topology="ring")
print(f"one population of 200: f = {single.f[0]:.4f} after {single.report['evaluations']} evaluations")
print(f"4 islands of 50:       f = {islands.f[0]:.4f} after {islands.report['evaluations']} evaluations")
