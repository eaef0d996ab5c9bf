# SPDX-License-Identifier: MIT
# offset: the dict `hula offset` prints for the same curve file, bit for bit,
# and closed forms (the concentric circle of a law circle, exact; the parabola
# y = x² offset towards its focus: two cusps, one loop at (0, 5/4)).
import math

import pytest

import hulahoops as hh
from conftest import hula


def parabola():
    return hh.NurbsCurve(2, [0, 0, 0, 1, 1, 1], [[-1, 1], [0, -1], [1, 1]])


def test_offset_is_the_cli_answer(tmp_path):
    # checks offset(curve, d) against `hula offset` on the same file, bit for bit, and the parabola's closed form
    parabola().save(str(tmp_path / "p.json"))
    ours = hh.offset(parabola(), 1.0, tolerance=1e-9)
    cli = hula("offset", tmp_path / "p.json", "--distance", "1", "--tolerance", "1e-9")
    assert ours == {k: v for k, v in cli.items() if k != "curve"}
    xc = math.sqrt((2 ** (2 / 3) - 1) / 4)
    assert ours["cusps"] == pytest.approx([(1 - xc) / 2, (1 + xc) / 2], abs=1e-12)
    assert len(ours["loops"]) == 1
    assert ours["loops"][0]["point"] == pytest.approx([0.0, 1.25], abs=1e-9)
    assert len(ours["trimmed"]) == 1 and len(ours["trimmed"][0]["spans"]) == 2


def test_offset_of_a_law_circle_is_an_exact_law():
    # checks a law circle's offset is a law curve (exact) on the concentric circle, trimmed to one closed piece
    circle = {"kind": "law", "expression": "vec(2*cos(t), 2*sin(t))", "domain": [0, 2 * math.pi]}
    ours = hh.offset(circle, 0.5)
    assert ours["exact"] is True
    assert ours["raw"]["kind"] == "law"
    assert ours["cusps"] == [] and ours["loops"] == []
    assert len(ours["trimmed"]) == 1 and ours["trimmed"][0]["closed"] is True
    piece = hh.NurbsCurve.from_json(ours["trimmed"][0]["curve"])
    assert math.hypot(*piece(0.3)) == pytest.approx(1.5, abs=1e-6)
    assert hh.offset(circle, 0.5, trim=False)["trimmed"] == []


def test_offset_refuses_a_space_curve():
    # checks a 3-D curve is refused with the curve named
    helix = {"kind": "law", "expression": "vec(cos(t), sin(t), t)", "domain": [0, 1]}
    with pytest.raises(hh.InvalidArgumentError) as e:
        hh.offset(helix, 1.0)
    assert e.value.where["field"] == "curve"


def test_helical_offset_is_the_cli_answer(tmp_path):
    # checks helical_offset against `hula helical-offset` on the same file (summary and written curve file), and
    # the toroidal helix ((2 - 0.5 cos 8t) cos t, (2 - 0.5 cos 8t) sin t, 0.5 sin 8t) of thesis 6.5.2 (closed form)
    import json
    circle = {"kind": "law", "expression": "vec(2*cos(t), 2*sin(t))", "domain": [0, 2 * math.pi]}
    (tmp_path / "c.json").write_text(json.dumps(circle))
    ours = hh.helical_offset(circle, "0.5", twist="8*t")
    cli = hula("helical-offset", tmp_path / "c.json", "--distance", "0.5", "--twist", "8*t",
               "-o", tmp_path / "h.json")
    assert {k: v for k, v in ours.items() if k != "curve"} == {k: v for k, v in cli.items()
                                                               if k not in ("input", "output")}
    assert json.loads((tmp_path / "h.json").read_text()) == ours["curve"]
    assert ours["exact"] is True and ours["curve"]["kind"] == "law"
    helix = hh.Law(ours["curve"]["expression"])
    for t in (0.0, 0.7, 2.5):
        want = [(2 - 0.5 * math.cos(8 * t)) * math.cos(t), (2 - 0.5 * math.cos(8 * t)) * math.sin(t),
                0.5 * math.sin(8 * t)]
        assert list(helix(t)) == pytest.approx(want, abs=1e-14)


def test_helical_offset_of_a_line_needs_the_bishop_frame():
    # checks a straight line's Frenet frame is refused naming the frame, its Bishop offset is the helix of radius d
    line = {"kind": "law", "expression": "vec(t, 0, 0)", "domain": [0, 4]}
    with pytest.raises(hh.NumericalFailureError) as e:
        hh.helical_offset(line, "0.5", twist="3*t")
    assert e.value.where["field"] == "frame"
    ours = hh.helical_offset(line, "0.5", twist="3*t", frame="bishop")
    assert ours["exact"] is True
    assert len(ours["plane_normal"]) == 3
    with pytest.raises(hh.InvalidOptionError):
        hh.helical_offset(line, "0.5", frame="darboux")


def test_orthotomic_and_polar_are_the_cli_answers(tmp_path):
    # checks orthotomic / polar_map against `hula orthotomic` / `hula polar` on the same file, and closed forms:
    # the parabola's orthotomic about its focus is the directrix y = -1/4; its polar map about the unit circle
    # is y = -x^2/4
    import json
    parabola_law = {"kind": "law", "expression": "vec(t, t^2)", "domain": [0.5, 2]}
    (tmp_path / "p.json").write_text(json.dumps(parabola_law))
    ours = hh.orthotomic(parabola_law, [0, 0.25], k=2)
    cli = hula("orthotomic", tmp_path / "p.json", "--pole", "0,0.25", "-o", tmp_path / "o.json")
    assert {k: v for k, v in ours.items() if k != "curve"} == {k: v for k, v in cli.items()
                                                               if k not in ("input", "output")}
    assert json.loads((tmp_path / "o.json").read_text()) == ours["curve"]
    o = hh.Law(ours["curve"]["expression"])
    assert [o(t)[1] for t in (0.5, 1.0, 2.0)] == pytest.approx([-0.25] * 3, abs=1e-15)
    polar = hh.polar_map(parabola_law, [0, 0])
    cli = hula("polar", tmp_path / "p.json", "--centre", "0,0", "-o", tmp_path / "q.json")
    assert json.loads((tmp_path / "q.json").read_text()) == polar["curve"]
    q = hh.Law(polar["curve"]["expression"])
    for t in (0.5, 1.0, 2.0):
        x, y = q(t)
        assert y == pytest.approx(-x * x / 4, abs=1e-14)


def test_hermite_frenet_is_the_cli_curve(tmp_path):
    # checks hermite_frenet against `hula hermite-frenet` on the same handle file (the written curve, bit for bit)
    # and that the curve has the handles' curvature 1/2 and torsion 0 (a circle of radius 2, closed form)
    import json
    handles = []
    for i in range(5):
        s = i * math.pi / 4
        handles.append({"point": [2 * math.cos(s), 2 * math.sin(s)],
                        "tangent": [-2 * math.pi * math.sin(s), 2 * math.pi * math.cos(s)],
                        "normal": [-math.cos(s), -math.sin(s)], "curvature": 0.5})
    doc = {"handles": handles, "parameters": [0, 0.25, 0.5, 0.75, 1]}
    (tmp_path / "h.json").write_text(json.dumps(doc))
    ours = hh.hermite_frenet(doc)
    hula("hermite-frenet", tmp_path / "h.json", "-o", tmp_path / "c.json")
    assert json.loads(ours.to_json()) == json.loads((tmp_path / "c.json").read_text())
    a = hh.analyse(ours, at=[0, 0.25, 0.5, 0.75, 1])
    assert list(a["curvature"]) == pytest.approx([0.5] * 5, abs=1e-12)
    with pytest.raises(hh.ParseError):
        hh.hermite_frenet({"handles": [{"point": [0, 0], "tangent": [1, 0], "twist": 1}]})


def test_closed_interpolation_and_degree_reduction_are_the_cli_answers(tmp_path):
    # checks interpolate(closed=True) against `hula interpolate --closed` (bit for bit) and the square's closed form
    # C(1/8) = (11/16, 11/16); reduce_degree against `hula edit reduce-degree`: an elevated curve comes back
    import json
    square = [[1, 0], [0, 1], [-1, 0], [0, -1]]
    ring = hh.interpolate(square, closed=True, parameterisation="uniform")
    assert list(ring(0.125)) == pytest.approx([0.6875, 0.6875], abs=1e-15)
    (tmp_path / "sq.json").write_text(json.dumps(square))
    hula("interpolate", "--points", tmp_path / "sq.json", "--closed", "--parameterisation", "uniform",
         "-o", tmp_path / "ring.json")
    assert json.loads(ring.to_json()) == json.loads((tmp_path / "ring.json").read_text())
    quartic = ring.elevate(1)
    back = quartic.reduce_degree(0.0)
    assert back["curve"].degree == 3 and back["error_bound"] < 1e-12
    assert list(back["curve"](0.3)) == pytest.approx(list(ring(0.3)), abs=1e-12)
    quartic.save(str(tmp_path / "q.json"))
    cli = hula("edit", "reduce-degree", tmp_path / "q.json", "--tolerance", "0", "-o", tmp_path / "c.json")
    assert cli["error_bound"] == back["error_bound"]
    assert json.loads(back["curve"].to_json()) == json.loads((tmp_path / "c.json").read_text())


def full_circle(r):
    # The circle of radius r as four rational quadratic arcs (The NURBS Book ex. 7.2).
    w = math.sqrt(0.5)
    pts = [[r, 0], [r, r], [0, r], [-r, r], [-r, 0], [-r, -r], [0, -r], [r, -r], [r, 0]]
    return hh.NurbsCurve(2, [0, 0, 0, .25, .25, .5, .5, .75, .75, 1, 1, 1], pts, weights=[1, w, 1, w, 1, w, 1, w, 1])


def test_rebuild_is_the_cli_answer_and_measures_its_deviation(tmp_path):
    # checks NurbsCurve.rebuild against `hula edit rebuild` (report and curve bit for bit); a cubic rebuilt with more
    # control points is reproduced (1e-12), and a circle's reported deviation is the closed form ||C(s)| - R| at the
    # same 1,001 samples (to 1e-9)
    import json
    cubic = hh.NurbsCurve(3, [0, 0, 0, 0, 1, 1, 1, 1], [[0, 0, 0], [1, 2, 0], [3, 2, 1], [4, 0, 0]])
    r = cubic.rebuild(9)
    assert r["curve"].degree == 3 and len(r["curve"].control_points) == 9
    assert r["max_deviation"] < 1e-12 * 5
    for t in (0.0, 0.1, 0.37, 0.5, 0.93, 1.0):
        assert list(r["curve"](t)) == pytest.approx(list(cubic(t)), abs=1e-12)
    ring = full_circle(2.0)
    ours = ring.rebuild(14, degree=3)
    s = [i / 1000 for i in range(1001)]
    worst = max(abs(math.hypot(*ours["curve"](t)) - 2.0) for t in s)
    assert ours["max_deviation"] == pytest.approx(worst, abs=2e-9)
    ring.save(str(tmp_path / "ring.json"))
    cli = hula("edit", "rebuild", tmp_path / "ring.json", "--degree", "3", "--control-points", "14",
               "-o", tmp_path / "out.json")
    assert {k: v for k, v in ours.items() if k != "curve"} == {k: v for k, v in cli.items()
                                                             if k not in ("operation", "curve")}
    assert json.loads(ours["curve"].to_json()) == json.loads((tmp_path / "out.json").read_text())
    with pytest.raises(hh.InvalidOptionError) as e:
        cubic.rebuild(3)
    assert e.value.where["field"] == "control_points"


def test_reduce_degree_takes_a_rational_curve():
    # checks a degree-elevated rational circle reduces back exactly: bound at rounding level, |C(t)| = R (closed
    # form) at 201 parameters, the weights w_i / w_0 of the original
    ring = full_circle(1.5)
    back = ring.elevate(1).reduce_degree(0.0)
    assert back["curve"].degree == 2 and back["error_bound"] < 1e-11
    for i in range(201):
        assert math.hypot(*back["curve"](i / 200)) == pytest.approx(1.5, abs=1e-12)
    w = list(back["curve"].weights)
    assert [x / w[0] for x in w] == pytest.approx(list(ring.weights), abs=1e-12)
