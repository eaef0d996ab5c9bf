# SPDX-License-Identifier: MIT
# Ctrl-C in the long C++ loops: a child process runs hh.optimise or a study
# that would go on for minutes, the test sends it SIGINT and the child reports
# when its `except KeyboardInterrupt` ran (CLOCK_MONOTONIC is one clock for
# both processes) and what the exception's `result` held: the best so far.
import json
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

from conftest import SOURCE, hula

CHILD = r"""
import json, math, sys, time
import numpy as np
import hulahoops as hh

kind = sys.argv[1]
print("ready", flush=True)
try:
    if kind == "builtin":
        hh.optimise("rastrigin", dimension=10, population=60, generations=10**9, seed=3, wall_time=120)
    elif kind == "python":
        problem = hh.Problem(lambda X: np.sum((X - 0.25) ** 2, axis=1), -np.ones(4), np.ones(4))
        hh.optimise(problem, population=40, generations=10**9, seed=5, wall_time=120)
    elif kind == "pagmo":
        problem = hh.Problem(lambda X: np.sum((X - 0.25) ** 2, axis=1), -np.ones(4), np.ones(4))
        hh.optimise(problem, "pagmo-pso", population=20, generations=10**9, seed=5, wall_time=120)
    elif kind == "nsga2":
        hh.optimise("zdt1", "nsga2", dimension=8, population=40, generations=10**9, seed=2, wall_time=120)
    elif kind == "study":
        setup = json.loads(open(sys.argv[2]).read())
        setup["ga"]["generations"] = 10**6
        hh.match_curvature(setup)
    elif kind == "fairknots":
        # Nelder-Mead on the parameters of 60 points, with no tolerance and no budget to end it
        points = [[100 * math.cos(t / 5), 60 * math.sin(t / 3) + t % 3] for t in range(60)]
        hh.fair_knots({"format": "hula-study", "version": 1, "study": "fair-knots", "points": points,
                       "energy": "bending", "method": "deterministic",
                       "deterministic": {"max_evaluations": 10**8, "x_tolerance": 0, "f_tolerance": 0,
                                         "restarts": 1000}})
    elif kind == "docrun":
        setup = json.loads(open(sys.argv[2]).read())
        setup["ga"]["generations"] = 10**6
        doc = hh.Document.create(sys.argv[3])
        doc.add_points(setup["points"], name="data")
        setup["points"] = {"entity": 1}
        generations = []
        doc.run(setup, callback=lambda g, best, evaluations: generations.append(time.monotonic()))
    print(json.dumps({"finished": True}), flush=True)
except KeyboardInterrupt as e:
    caught = time.monotonic()
    r = e.result
    out = {"caught": caught, "type": type(r).__name__}
    if kind in ("builtin", "python", "pagmo"):
        out.update(termination=r.report["termination"], f=float(r.f[0]), x=r.x.tolist(),
                   best=r.best_per_generation.tolist())
    elif kind == "nsga2":
        out.update(termination=r.report["termination"], front=r.front_f.tolist())
    elif kind == "docrun":
        out.update(last_generation=generations[-1], generations=len(generations),
                   cancelled=r["cancelled"], labels=r["result_labels"], revision=r["revision"],
                   best_points=r["best_points"], history=doc.history()[-1]["name"])
        doc.close()
    elif kind == "fairknots":
        out.update(termination=r.deterministic.termination, energy=r.deterministic.energy,
                   chord=r.chord_length.energy, iterations=len(r.deterministic.convergence),
                   convergence_min=min(r.deterministic.convergence))
    else:
        out.update(best_points=np.asarray(r.best_points).tolist(), termination=r.ga.termination,
                   after=r.after.mean, before=r.before.mean)
    print(json.dumps(out), flush=True)
"""


def interrupt(kind, *args, after=0.5):
    """Starts the child, sends SIGINT `after` seconds into its run and returns (seconds from the signal to
    the child's except clause, the child's report)."""
    child = subprocess.Popen([sys.executable, "-c", CHILD, kind, *map(str, args)], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
    try:
        assert child.stdout.readline().strip() == "ready"
        time.sleep(after)
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=60)
    finally:
        if child.poll() is None:
            child.kill()
    assert child.returncode == 0, err
    report = json.loads(out.strip().splitlines()[-1])
    assert "finished" not in report, "the run ended before the signal"
    return report["caught"] - sent, report


@pytest.mark.parametrize("kind", ["builtin", "python", "pagmo"])
def test_sigint_stops_optimise_with_the_best_so_far(kind):
    # checks SIGINT ends a GA run (built-in problem, then a Python objective) and a pagmo PSO run (Python
    # objective: pagmo's own loop, stopped by the adapter before an evaluation) in < 0.5 s and the exception's
    # result is the best so far: termination Cancelled, f = the smallest best of all generations (pagmo: at
    # most that, its evaluations since the last whole generation count too) and the objective at x, x inside
    # the bounds
    latency, r = interrupt(kind)
    assert 0 <= latency < 0.5, latency
    assert r["type"] == "OptimiseResult"
    assert r["termination"] == "Cancelled"
    assert len(r["best"]) > 2  # several generations ran before the signal
    if kind == "pagmo":
        assert r["f"] <= min(r["best"])
    else:
        assert r["f"] == min(r["best"])
    assert np.isfinite(r["f"])
    if kind in ("python", "pagmo"):
        x = np.array(r["x"])
        assert np.all(np.abs(x) <= 1) and r["f"] == pytest.approx(np.sum((x - 0.25) ** 2), rel=1e-12, abs=0)


def test_sigint_stops_nsga2_with_its_front():
    # checks SIGINT ends an NSGA-II run on ZDT1 in < 0.5 s with a non-empty, mutually non-dominated front
    latency, r = interrupt("nsga2")
    assert 0 <= latency < 0.5, latency
    assert r["termination"] == "Cancelled"
    front = np.array(r["front"])
    assert front.shape[0] >= 1 and front.shape[1] == 2
    for a in front:
        assert not np.any(np.all(front <= a, axis=1) & np.any(front < a, axis=1))


def test_sigint_stops_a_study_with_its_best_points():
    # checks SIGINT ends a match-curvature GA of a million generations in < 0.5 s with the best points so
    # far: the GA's termination Cancelled, the fixed points unchanged, the free one within its offsets
    # (x 5 - 30 ... 5 + 35, y 20 +- 30) and a closer fit to the target than the start
    latency, r = interrupt("study", SOURCE / "examples" / "studies" / "match-curvature-example1.json")
    assert 0 <= latency < 0.5, latency
    assert r["type"] == "StudyResult"
    p = np.array(r["best_points"])
    assert p[0].tolist() == [0, 0] and p[2].tolist() == [40, 0]
    assert -25 - 1e-3 <= p[1][0] <= 40 + 1e-3 and -10 - 1e-3 <= p[1][1] <= 50 + 1e-3
    assert r["termination"] == "Cancelled" and r["after"] < r["before"]


def test_sigint_stops_a_deterministic_fair_knots_study():
    # checks SIGINT ends a fair-knots Nelder-Mead run that no tolerance or budget would end in < 0.5 s with
    # the best parameters so far: termination Cancelled, several iterations made, the energy at or below its
    # convergence graph's (the best at the start of each iteration) and below the chord-length start's
    latency, r = interrupt("fairknots")
    assert 0 <= latency < 0.5, latency
    assert r["type"] == "StudyResult"
    assert r["termination"] == "Cancelled" and r["iterations"] > 2
    assert r["energy"] <= r["convergence_min"] * (1 + 1e-12) and r["energy"] < r["chord"]


def test_sigint_stops_a_document_run_and_stores_the_best_so_far(tmp_path):
    # checks SIGINT stops Document.run of a match-curvature GA of a million generations within 0.5 s (its last
    # generation ends < 0.5 s after the signal), the run is then stored as `hula doc run` stores an interrupted
    # one ("cancelled", the best so far as a result curve, one "run study" step) before KeyboardInterrupt is
    # raised, the free point lies within its offsets, and `hula doc show` reads the result curve with the
    # study as its provenance. Storing the run stores its log (every individual of every generation) as one
    # column block, a fraction of the run (0.2 s from signal to exception, 3.0 s when each individual was a
    # JSON tree: docs/benchmarks.md): the exception comes after that, bounded here at 1.5 s.
    path = tmp_path / "run.hula"
    latency, r = interrupt("docrun", SOURCE / "examples" / "studies" / "match-curvature-example1.json", path)
    stopped = r["last_generation"] - (r["caught"] - latency)
    assert stopped < 0.5, stopped
    assert 0 <= latency < 1.5, latency
    assert r["generations"] > 2 and r["cancelled"] is True and r["history"] == "run study" and r["revision"] == 2
    p = np.array(r["best_points"])
    assert p[0].tolist() == [0, 0] and p[2].tolist() == [40, 0]
    assert -25 - 1e-3 <= p[1][0] <= 40 + 1e-3 and -10 - 1e-3 <= p[1][1] <= 50 + 1e-3
    shown = hula("doc", "show", path, r["labels"][0])
    provenance = shown["provenance"]
    assert provenance["operation"] == "study:match-curvature" and provenance["inputs"] == [2, 1], provenance
    assert provenance["details"]["cancelled"] is True, provenance
