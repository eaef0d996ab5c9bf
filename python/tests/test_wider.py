# SPDX-License-Identifier: MIT
# The wider bindings against independent references: pagmo's algorithms and
# NSGA-II's hypervolume against `hula optimise` on the same problem and seed
# and against a closed-form 2-D hypervolume; approximate against `hula
# approximate` and against points on a line.
import json

import numpy as np
import pytest

import hulahoops as hh
from conftest import hula


def hypervolume_2d(front, reference):
    """The area dominated by a 2-D front and bounded by the reference point (a sweep over f0)."""
    pts = sorted((float(a), float(b)) for a, b in front if a < reference[0] and b < reference[1])
    area, best_f1 = 0.0, reference[1]
    for i, (a, b) in enumerate(pts):
        nxt = pts[i + 1][0] if i + 1 < len(pts) else reference[0]
        best_f1 = min(best_f1, b)
        area += (nxt - a) * (reference[1] - best_f1)
    return area


@pytest.mark.parametrize("algorithm", ["pagmo-de", "pagmo-sade", "pagmo-pso"])
def test_pagmo_algorithm_is_the_cli_run(algorithm):
    # checks pagmo's DE, SADE and PSO through optimise give `hula optimise`'s best point bit for bit on
    # sphere-3 (minimum 0 at the origin) and come near it
    cli = hula("optimise", "--problem", "sphere", "--dimension", 3, "--algorithm", algorithm, "--population", 20,
               "--generations", 60, "--seed", 9)
    r = hh.optimise("sphere", algorithm, dimension=3, population=20, generations=60, seed=9)
    assert r.x.tolist() == cli["best"]["variables"] and r.f.tolist() == cli["best"]["objectives"]
    assert r.report["algorithm"] == algorithm
    assert 0 <= r.f[0] < 1e-2


def test_pagmo_refuses_what_it_does_not_take():
    # checks options pagmo's loop does not read are refused by name, not ignored
    with pytest.raises(hh.InvalidOptionError) as e:
        hh.optimise("sphere", "pagmo-de", dimension=2, max_evaluations=100)
    assert e.value.where["field"] == "max_evaluations"
    with pytest.raises(hh.InvalidArgumentError):
        hh.optimise("sphere", "pagmo-nonesuch", dimension=2)


def test_nsga2_hypervolume_is_the_cli_value_and_the_area():
    # checks ZDT1's NSGA-II front comes with the hypervolume `hula optimise` prints (reference 1.1, 1.1) and
    # that it is the area a 2-D sweep computes from the front
    cli = hula("optimise", "--problem", "zdt1", "--dimension", 6, "--algorithm", "nsga2", "--population", 24,
               "--generations", 30, "--seed", 3)
    r = hh.optimise("zdt1", "nsga2", dimension=6, population=24, generations=30, seed=3)
    assert r.reference.tolist() == [1.1, 1.1]
    assert r.hypervolume == cli["hypervolume"]
    assert r.hypervolume == pytest.approx(hypervolume_2d(r.front_f, [1.1, 1.1]), rel=1e-12)
    # ZDT1's true front f1 = 1 - sqrt(f0) bounds it: 1.1^2 - 1/3 is the ideal
    assert 0.5 < r.hypervolume < 1.1 ** 2 - 1 / 3


def test_hypervolume_of_a_python_problem_with_its_reference():
    # checks a Python bi-objective problem (f = (x, 1 - x) + penalty on y) gets the hypervolume of its front
    # against the reference given, equal to the 2-D sweep; none without a reference
    def f(X):
        return np.column_stack([X[:, 0] + X[:, 1] ** 2, 1 - X[:, 0] + X[:, 1] ** 2])

    p = hh.Problem(f, [0, -1], [1, 1], objectives=2)
    r = hh.optimise(p, "nsga2", population=20, generations=20, seed=1, reference=[1.0, 1.0])
    assert r.hypervolume == pytest.approx(hypervolume_2d(r.front_f, [1, 1]), rel=1e-12)
    assert 0 < r.hypervolume < 0.5
    assert hh.optimise(p, "nsga2", population=20, generations=2, seed=1).hypervolume is None
    with pytest.raises(hh.InvalidOptionError):
        hh.optimise(p, "nsga2", population=20, generations=2, reference=[1.0])


def test_approximate_is_the_cli_curve(tmp_path):
    # checks approximate with a tolerance and with a control-point count gives `hula approximate`'s curve and
    # report bit for bit on samples of an elliptic helix
    t = np.linspace(0, 2 * np.pi, 50)
    pts = np.column_stack([10 * np.cos(t), 6 * np.sin(t), t])
    path = tmp_path / "helix.json"
    path.write_text(json.dumps(pts.tolist()))
    for flag, key, value in (("--tolerance", "tolerance", 1e-3), ("--control-points", "control_points", 12)):
        cli = hula("approximate", "--points", path, flag, value, "-o", tmp_path / "out.json")
        curve, report = hh.approximate(pts, **{key: value})
        written = json.loads((tmp_path / "out.json").read_text())
        assert curve.control_points.tolist() == written["control_points"]
        assert curve.knots.tolist() == written["knots"]
        assert report["max_deviation"] == cli["max_deviation"]
        if key == "tolerance":
            assert report["max_deviation"] <= 1e-3
        else:
            assert report["control_points"] == 12


def test_approximate_collinear_points_is_the_line():
    # checks a least-squares cubic through points on y = 2x + 1 has every control point on that line
    x = np.linspace(-1, 3, 25)
    curve, report = hh.approximate(np.column_stack([x, 2 * x + 1]), control_points=6)
    cp = curve.control_points
    assert np.max(np.abs(cp[:, 1] - (2 * cp[:, 0] + 1))) < 1e-12
    assert report["max_deviation"] < 1e-12
    with pytest.raises(hh.InvalidArgumentError) as e:
        hh.approximate(np.column_stack([x, x]))
    assert e.value.where["field"] == "tolerance"


def test_clothoid_g1_closed_forms():
    # checks G1 Hermite data of a quarter of the unit circle gives that arc (kappa 1, dkappa 0, length pi/2)
    # and collinear data the segment (kappa 0, length 2)
    arc = hh.clothoid_g1([0, 0], 0.0, [1, 1], np.pi / 2)["segments"][0]
    assert arc["kappa0"] == pytest.approx(1, abs=1e-12) and arc["dkappa"] == pytest.approx(0, abs=1e-12)
    assert arc["length"] == pytest.approx(np.pi / 2, rel=1e-13)
    line = hh.clothoid_g1([0, 0], 0.0, [2, 0], 0.0)["segments"][0]
    assert line["kappa0"] == 0 and line["dkappa"] == 0 and line["length"] == pytest.approx(2, rel=1e-15)


def test_clothoid_g2_reproduces_a_circle_and_is_g2():
    # checks G2 data taken from a circle of radius 2 (kappa 0.5 at both ends, a quarter turn) gives three
    # arcs of curvature 0.5 summing to the quarter circle's length pi, joined with equal angle and curvature
    r = hh.clothoid_g2([2, 0], np.pi / 2, 0.5, [0, 2], np.pi, 0.5)
    segs = r["segments"]
    assert len(segs) == 3
    assert r["length"] == pytest.approx(np.pi, rel=1e-9)
    for s in segs:
        assert s["kappa0"] == pytest.approx(0.5, abs=1e-9) and s["dkappa"] == pytest.approx(0, abs=1e-9)
    for a, b in zip(segs, segs[1:]):
        assert a["theta1"] == pytest.approx(b["theta0"], abs=1e-12)
        assert a["kappa1"] == pytest.approx(b["kappa0"], abs=1e-12)


def test_clothoid_spline_closed_g2_and_biarcs(tmp_path):
    # checks a closed G2 spline through a seeded loop joins with position, angle and curvature equal to 1e-9 at every
    # point (the closing one too) and ends on each point; its "curve" is the natural curve file `hula clothoid -o`
    # writes for the same points (same JSON); points on a circle of radius 3 give kappa 1/3 everywhere; biarcs of the
    # loop are G1 with dkappa 0; the biarc of symmetric data is one circle (kappa = -2 sin(phi0) / d)
    rng = np.random.default_rng(26)
    t = np.sort(rng.uniform(0, 2 * np.pi, 7))
    rho = 1 + 0.3 * rng.uniform(-1, 1, 7)
    pts = np.column_stack([rho * np.cos(t), rho * np.sin(t)])
    r = hh.clothoid_spline(pts, closed=True)
    segs = r["segments"]
    assert (r["kind"], r["through"], r["closed"], len(segs)) == ("g2", 7, True, 7)
    for i, a in enumerate(segs):
        b = segs[(i + 1) % 7]
        assert np.hypot(a["end"][0] - b["start"][0], a["end"][1] - b["start"][1]) < 1e-9
        assert abs(np.remainder(a["theta1"] - b["theta0"] + np.pi, 2 * np.pi) - np.pi) < 1e-9
        assert abs(a["kappa1"] - b["kappa0"]) < 1e-9
        assert np.hypot(*(np.array(a["end"]) - pts[(i + 1) % 7])) < 1e-9
    path = tmp_path / "pts.json"
    path.write_text(json.dumps(pts.tolist()))
    out = tmp_path / "loop.json"
    hula("clothoid", "--points", str(path), "--closed", "-o", str(out))
    assert json.loads(out.read_text()) == r["curve"]
    circle = [[3 * np.cos(a), 3 * np.sin(a)] for a in (0.2, 0.9, 1.5, 2.6, 3.1)]
    for c in (1, 2):
        for s in hh.clothoid_spline(circle, continuity=c)["segments"]:
            assert s["kappa0"] == pytest.approx(1 / 3, abs=1e-10) and s["dkappa"] == pytest.approx(0, abs=1e-10)
    b = hh.clothoid_spline(pts, closed=True, biarc=True)
    assert b["kind"] == "biarc" and len(b["segments"]) == 14
    for i, a in enumerate(b["segments"]):
        n = b["segments"][(i + 1) % 14]
        assert a["dkappa"] == 0
        assert np.hypot(a["end"][0] - n["start"][0], a["end"][1] - n["start"][1]) < 1e-9
        assert abs(np.remainder(a["theta1"] - n["theta0"] + np.pi, 2 * np.pi) - np.pi) < 1e-9
    one = hh.biarc([0, 0], 0.4, [2, 0], -0.4)
    assert [s["kappa0"] for s in one["segments"]] == pytest.approx([-np.sin(0.4)] * 2, abs=1e-15)
    with pytest.raises(hh.InvalidArgumentError) as e:
        hh.clothoid_spline(pts, closed=True, start_curvature=0.3)
    assert e.value.where["field"] == "start_curvature"


def test_clothoid_spline_end_curvatures_reproduce_a_circle():
    # checks points on a circle of radius 2 with the curvature 0.5 given at one or both ends (an angle at the
    # other) give that circle: kappa 0.5 and dkappa 0 on every segment, the length 2 times the angle swept
    t = [0.1, 0.8, 1.5, 2.6, 3.0]
    pts = [[2 * np.cos(a), 2 * np.sin(a)] for a in t]
    for ends in ({"start_curvature": 0.5, "end_curvature": 0.5}, {"end_curvature": 0.5},
                 {"start_angle": 0.1 + np.pi / 2, "end_curvature": 0.5}):
        r = hh.clothoid_spline(pts, **ends)
        for s in r["segments"]:
            assert s["kappa0"] == pytest.approx(0.5, abs=1e-11) and s["dkappa"] == pytest.approx(0, abs=1e-11)
        assert r["length"] == pytest.approx(2 * (3.0 - 0.1), rel=1e-11)
    with pytest.raises(hh.InvalidArgumentError) as e:
        hh.clothoid_spline(pts, start_angle=0.3, start_curvature=0.5)
    assert e.value.where["field"] == "start_curvature"


def test_fit_is_the_cli_fit(tmp_path):
    # checks fit on a noisy sine (seeded) gives the curve and figures `hula fit --class A` gives, bit for bit,
    # with every kept point within the class-A tolerance 0.3
    rng = np.random.default_rng(5)
    x = np.linspace(0, 100, 80)
    pts = np.column_stack([x, 10 * np.sin(x / 15) + rng.normal(0, 0.05, x.size)])
    csv = tmp_path / "wave.csv"
    np.savetxt(csv, pts, delimiter=",", fmt="%.17g")  # 17 significant digits: the same doubles
    cli = hula("fit", "--points", csv, "--class", "A", "-o", tmp_path / "out.json")
    r = hh.fit({"format": "hula-study", "version": 1, "study": "fit", "points": pts.tolist(), "class": "A"})
    written = json.loads((tmp_path / "out.json").read_text())
    assert r.curve.control_points.tolist() == written["control_points"]
    assert r.curve.knots.tolist() == written["knots"]
    for key in ("max_deviation", "mean_deviation", "control_points", "inflections", "bending"):
        assert r.after[key] == cli["after"][key], key
    assert r.tolerance == 0.3 and r.after.max_deviation <= 0.3
