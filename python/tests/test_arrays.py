# SPDX-License-Identifier: MIT
# NumPy interop policy (python/src/arrays.hpp): strided views and other real
# dtypes are converted, exactly; non-real dtypes and wrong shapes are refused
# naming the argument, its dtype or shape.
import numpy as np
import pytest

import hulahoops as hh


def test_non_contiguous_t_gives_the_same_values(space_curve):
    # checks a strided (every third) and a reversed view against the contiguous copy, bit for bit
    t = np.linspace(0, 1, 300)
    assert np.array_equal(space_curve(t[::3]), space_curve(np.ascontiguousarray(t[::3])))
    assert np.array_equal(space_curve(t[::-1]), space_curve(t.copy()[::-1].copy()))
    grid = np.linspace(0, 1, 60).reshape(6, 10).T  # Fortran order
    assert np.array_equal(space_curve(grid), space_curve(np.ascontiguousarray(grid)))


def test_non_contiguous_control_points():
    # checks that a column-sliced (non-contiguous) control-point array builds the same curve
    big = np.arange(24, dtype=float).reshape(4, 6)
    pts = big[:, ::2]  # (4, 3), stride 16 bytes
    assert not pts.flags["C_CONTIGUOUS"]
    a = hh.NurbsCurve(3, [0, 0, 0, 0, 1, 1, 1, 1], pts)
    b = hh.NurbsCurve(3, [0, 0, 0, 0, 1, 1, 1, 1], np.ascontiguousarray(pts))
    assert a == b


def test_float32_and_integers_are_converted_exactly(space_curve):
    # checks float32 and int inputs give the result of their exact float64 values
    t32 = np.linspace(0, 1, 50, dtype=np.float32)
    assert np.array_equal(space_curve(t32), space_curve(t32.astype(np.float64)))
    assert np.array_equal(space_curve(np.array([0, 1])), space_curve(np.array([0.0, 1.0])))
    c = hh.NurbsCurve(1, np.array([0, 0, 1, 1], dtype=np.int32), np.array([[0, 0], [3, 4]], dtype=np.float32))
    assert c.arc_length() == pytest.approx(5.0, abs=1e-15)


def test_non_real_dtypes_are_refused_by_name(space_curve):
    # checks complex, bool and string inputs are refused with the argument's name and dtype
    with pytest.raises(hh.InvalidArgumentError, match="t has dtype complex128"):
        space_curve(np.array([0.5 + 0j]))
    with pytest.raises(hh.InvalidArgumentError, match="t has dtype bool"):
        space_curve(np.array([True]))
    with pytest.raises(hh.InvalidArgumentError) as e:
        hh.interpolate(np.array([["a", "b"], ["c", "d"]]))
    assert e.value.where["field"] == "points"


def test_wrong_shapes_are_refused_naming_the_shape():
    # checks wrong shapes of points, control points and out are refused with the shape received
    with pytest.raises(hh.InvalidArgumentError, match=r"points has shape \(4, 5\)"):
        hh.interpolate(np.zeros((4, 5)))
    with pytest.raises(hh.InvalidArgumentError, match=r"control_points has shape \(6,\)"):
        hh.NurbsCurve(1, [0, 0, 1, 1], np.zeros(6))
    c = hh.NurbsCurve(1, [0, 0, 1, 1], [[0, 0, 0], [1, 1, 1]])
    with pytest.raises(hh.InvalidArgumentError, match=r"out has shape \(3, 2\)"):
        c(np.zeros(3), out=np.zeros((3, 2)))
    with pytest.raises(hh.InvalidArgumentError, match=r"point has shape \(4,\)"):
        c.closest_point([1, 2, 3, 4])


def test_planar_results_are_views_of_two_columns():
    # checks planar curves return (n, 2) arrays holding x, y of the 3-D evaluation
    c = hh.NurbsCurve(1, [0, 0, 1, 1], [[0, 0], [2, 1]])
    p = c(np.array([0.25, 0.5]))
    assert p.shape == (2, 2)
    assert np.array_equal(p, [[0.5, 0.25], [1.0, 0.5]])
