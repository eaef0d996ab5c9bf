# SPDX-License-Identifier: MIT
# NurbsCurve and interpolate: every binding against the C++ results of the
# `hula` CLI to the last bit, and against closed forms.
import math
import pickle

import numpy as np
import pytest

import hulahoops as hh
from conftest import SOURCE, hula, numbers


def test_evaluate_matches_cli_bit_for_bit(space_curve, tmp_path):
    # checks curve(t) over an array against `hula eval` on the same curve file, bit for bit
    path = tmp_path / "c.json"
    space_curve.save(str(path))
    t = np.random.default_rng(1).uniform(0, 1, 40)
    cli = hula("eval", path, "--at", numbers(t))
    expected = np.array([r["derivatives"][0] for r in cli["results"]])
    assert np.array_equal(space_curve(t), expected)


def test_derivatives_match_cli_bit_for_bit(space_curve, tmp_path):
    # checks curve.derivatives(t, 3) against `hula eval --derivatives 3`, bit for bit, incl. the left limit at a knot
    path = tmp_path / "c.json"
    space_curve.save(str(path))
    t = np.array([0.0, 0.3, 0.5, 0.7, 1.0])
    for side in ("right", "left"):
        cli = hula("eval", path, "--at", numbers(t), "--derivatives", 3, "--side", side)
        expected = np.array([r["derivatives"] for r in cli["results"]])
        assert np.array_equal(space_curve.derivatives(t, 3, side=side), expected)


def test_quarter_circle_closed_form(quarter_circle):
    # checks the rational evaluation against the unit circle: |C(t)| = 1, C(0) = (1, 0), C(1) = (0, 1)
    t = np.linspace(0, 1, 1001)
    p = quarter_circle(t)
    assert p.shape == (1001, 2)
    assert np.max(np.abs(np.hypot(p[:, 0], p[:, 1]) - 1)) < 1e-15
    assert np.array_equal(quarter_circle(0.0), [1.0, 0.0]) and np.allclose(quarter_circle(1.0), [0.0, 1.0], atol=0)
    assert quarter_circle.arc_length() == pytest.approx(math.pi / 2, abs=1e-12)


def test_shapes_follow_t(space_curve):
    # checks that t's shape is kept and the trailing axis is the dimension, and that out= is written in place
    assert space_curve(0.5).shape == (3,)
    assert space_curve(np.zeros((4, 5))).shape == (4, 5, 3)
    assert space_curve.derivatives(np.zeros(6), 2).shape == (6, 3, 3)
    out = np.empty((7, 3))
    t = np.linspace(0, 1, 7)
    assert space_curve(t, out=out) is out
    assert np.array_equal(out, space_curve(t))


def test_insert_elevate_split_keep_the_shape(space_curve):
    # checks knot insertion, degree elevation and splitting against the original curve's points (same geometry)
    t = np.linspace(0, 1, 201)
    c = space_curve(t)
    k = space_curve.insert_knot(0.5, 2)
    assert k.knots.size == space_curve.knots.size + 2
    assert np.max(np.abs(k(t) - c)) < 1e-13
    e = space_curve.elevate()
    assert e.degree == 4
    assert np.max(np.abs(e(t) - c)) < 1e-13
    before, after = space_curve.split(0.4)
    assert before.domain == (0.0, 0.4) and after.domain == (0.4, 1.0)
    assert np.max(np.abs(before(t[t <= 0.4]) - c[t <= 0.4])) < 1e-13
    assert np.max(np.abs(after(t[t >= 0.4]) - c[t >= 0.4])) < 1e-13


def test_arc_length_and_closest_point_on_a_line():
    # checks arc length and closest point against closed forms on the line from (0,0,0) to (3,4,0)
    line = hh.NurbsCurve(1, [0, 0, 1, 1], [[0, 0, 0], [3, 4, 0]])
    assert line.arc_length() == pytest.approx(5.0, abs=1e-14)
    assert line.arc_length(0.2, 0.6) == pytest.approx(2.0, abs=1e-14)
    assert line.parameter_at_length(2.5) == pytest.approx(0.5, abs=1e-14)
    cp = line.closest_point([3, 0, 0])
    # projection of (3,0) on direction (0.6, 0.8): 1.8 along the line, t = 0.36, distance 2.4
    assert cp.t == pytest.approx(0.36, abs=1e-12)
    assert cp.distance == pytest.approx(2.4, abs=1e-12)
    assert np.allclose(cp.point, [1.08, 1.44, 0], atol=1e-12)


def test_json_and_pickle_round_trip(space_curve, quarter_circle, tmp_path):
    # checks that save/load, to_json/from_json and pickle give back an equal curve
    for c in (space_curve, quarter_circle):
        path = tmp_path / "c.json"
        c.save(str(path))
        assert hh.NurbsCurve.load(str(path)) == c
        assert hh.NurbsCurve.from_json(c.to_json()) == c
        assert pickle.loads(pickle.dumps(c)) == c


def test_interpolate_matches_cli(tmp_path):
    # checks interpolate() against `hula interpolate` on the same points and end conditions, bit for bit
    pts = np.array([[0, 0], [40, 25], [80, -25], [120, 0], [150, 10.5]])
    (tmp_path / "p.json").write_text(str(pts.tolist()))
    for start, end, cli_start, cli_end in (("natural", "natural", "natural", "natural"),
                                           ([1, 0.5], "bessel", "clamped:1,0.5,0", "bessel")):
        hula("interpolate", "--points", tmp_path / "p.json", "--start", cli_start, "--end", cli_end,
             "-o", tmp_path / "c.json")
        expected = hh.NurbsCurve.load(str(tmp_path / "c.json"))
        got = hh.interpolate(pts, start=start, end=end)
        assert got == expected
        assert got.dimension == 2
    # and the curve passes through the points at the chord-length parameters
    c = hh.interpolate(pts)
    chords = np.concatenate([[0], np.cumsum(np.hypot(*np.diff(pts, axis=0).T))])
    assert np.max(np.abs(c(chords / chords[-1]) - pts)) < 1e-11


def test_read_points_takes_files_as_people_have_them(tmp_path):
    # checks read_points on a Selig airfoil file as shipped (name line, no final newline) against a plain
    # scan of its numeric lines, on a semicolon file with decimal commas, and that errors name the file
    dat = SOURCE / "tests" / "data" / "real" / "naca2412.dat"
    rows = [list(map(float, line.split())) for line in dat.read_text().splitlines()[1:] if line.strip()]
    pts = hh.read_points(str(dat))
    assert pts.shape == (len(rows), 2)
    assert np.array_equal(pts, np.array(rows))
    (tmp_path / "p.csv").write_text("x;y;z\n1,5;2;3\n4;5,25;6\n")
    assert np.array_equal(hh.read_points(str(tmp_path / "p.csv")), [[1.5, 2, 3], [4, 5.25, 6]])
    (tmp_path / "bad.txt").write_text("1 2\n3 x\n")
    with pytest.raises(hh.ParseError) as e:
        hh.read_points(str(tmp_path / "bad.txt"))
    assert "bad.txt: line 2, column 3" in e.value.message and "whitespace" in e.value.message
    with hh.Document.create(tmp_path / "d.hula") as doc:
        label = doc.add_points(dat, name="naca2412")
        assert doc.show(label)["points"] == pts.tolist()


def test_errors_carry_code_message_where(space_curve):
    # checks invalid input raises the Error subclass of its code with the faulty field and index named
    with pytest.raises(hh.InvalidKnotsError) as e:
        hh.NurbsCurve(1, [0, 0, 0.6, 0.5, 1, 1], [[0, 0], [1, 0], [1, 1], [0, 1]])
    assert e.value.code == "InvalidKnots" and e.value.where["field"] == "knots" and e.value.where["index"] == 3
    assert "0.5" in e.value.message
    assert isinstance(e.value, hh.Error)
    with pytest.raises(hh.OutOfDomainError) as e:
        space_curve(np.array([0.5, 1.5]))
    assert e.value.where.get("index") == 1
    assert np.array_equal(space_curve(1.5, domain="clamp"), space_curve(1.0))
    with pytest.raises(hh.InvalidArgumentError, match="domain"):
        space_curve(0.5, domain="wrap")
    with pytest.raises(hh.InvalidWeightError):
        hh.NurbsCurve(1, [0, 0, 1, 1], [[0, 0], [1, 0]], weights=[1, -1])
