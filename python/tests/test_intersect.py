# SPDX-License-Identifier: MIT
# intersect and distance: the dicts `hula intersect` / `hula distance` print for
# the same curve files, bit for bit, and closed forms (circle and secant, a
# cubic loop, a line above a circle).
import math

import pytest

import hulahoops as hh
from conftest import hula


@pytest.fixture
def circle():
    """The unit circle as four rational quadratic arcs."""
    w = math.sqrt(0.5)
    return hh.NurbsCurve(2, [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
                         [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]],
                         weights=[1, w, 1, w, 1, w, 1, w, 1])


def line(a, b):
    return hh.NurbsCurve(1, [0, 0, 1, 1], [a, b])


def test_intersect_is_the_cli_answer(circle, tmp_path):
    # checks intersect(a, b) against `hula intersect` on the same files, bit for bit, and x = ±√3/2 on y = 1/2
    secant = line([-2, 0.5], [2, 0.5])
    circle.save(str(tmp_path / "a.json"))
    secant.save(str(tmp_path / "b.json"))
    ours = hh.intersect(circle, secant)
    cli = hula("intersect", tmp_path / "a.json", tmp_path / "b.json")
    assert ours == {k: v for k, v in cli.items() if k not in ("a", "b")}
    assert sorted(round(p["point"][0], 12) for p in ours["points"]) == [round(-math.sqrt(3) / 2, 12),
                                                                        round(math.sqrt(3) / 2, 12)]
    assert all(p["kind"] == "crossing" and abs(p["angle"] - math.pi / 3) < 1e-12 for p in ours["points"])


def test_self_intersection_is_the_cli_answer(tmp_path):
    # checks intersect(a) (self) against `hula intersect --self`: a cubic loop meets itself once, s < t
    loop = hh.NurbsCurve(3, [0, 0, 0, 0, 1, 1, 1, 1], [[0, 0], [2, 1], [-1, 1], [1, 0]])
    loop.save(str(tmp_path / "loop.json"))
    ours = hh.intersect(loop)
    assert ours == {k: v for k, v in hula("intersect", tmp_path / "loop.json", "--self").items()
                    if k not in ("a", "self")}
    assert len(ours["points"]) == 1 and ours["points"][0]["s"] < ours["points"][0]["t"]


def test_distance_closed_form_and_cli(circle, tmp_path):
    # checks distance(a, b): a line at y = 4 is 3 from the unit circle, at its top; equal to `hula distance`
    high = line([-2, 4], [2, 4])
    circle.save(str(tmp_path / "a.json"))
    high.save(str(tmp_path / "b.json"))
    ours = hh.distance(circle, high, tolerance=1e-9)
    assert ours == {k: v for k, v in hula("distance", tmp_path / "a.json", tmp_path / "b.json", "--tolerance",
                                          "1e-9").items() if k not in ("a", "b")}
    assert abs(ours["distance"] - 3.0) < 1e-14
    assert abs(ours["point_a"][1] - 1.0) < 1e-12


def test_bad_tolerance_raises_invalid_option(circle):
    # checks a non-positive tolerance raises InvalidOptionError naming the field
    with pytest.raises(hh.InvalidOptionError) as e:
        hh.intersect(circle, circle, tolerance=0.0)
    assert "resabs" in str(e.value)
