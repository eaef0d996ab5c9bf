# SPDX-License-Identifier: MIT
# hh.read / hh.write: curve files by extension through the halves of `hula
# convert`. Round trips JSON -> STEP / IGES / DXF -> curves within 1e-12, and
# the files and curves are those of the CLI on the same input.
import json

import numpy as np
import pytest

import hulahoops as hh
from conftest import hula


def same_curve(a, b, tol=1e-12):
    assert a.degree == b.degree
    ka, kb = np.asarray(a.knots), np.asarray(b.knots)
    # a reader may rescale the domain: compare knots after mapping both onto [0, 1]
    ka = (ka - ka[0]) / (ka[-1] - ka[0])
    kb = (kb - kb[0]) / (kb[-1] - kb[0])
    assert np.max(np.abs(ka - kb)) <= tol
    pa, pb = np.asarray(a.control_points), np.asarray(b.control_points)
    assert pa.shape[0] == pb.shape[0]
    d = min(pa.shape[1], pb.shape[1])
    assert np.max(np.abs(pa[:, :d] - pb[:, :d])) <= tol * max(1.0, np.max(np.abs(pa)))
    assert np.all(pa[:, d:] == 0) and np.all(pb[:, d:] == 0)
    wa = np.ones(pa.shape[0]) if a.weights is None else np.asarray(a.weights)
    wb = np.ones(pb.shape[0]) if b.weights is None else np.asarray(b.weights)
    assert np.max(np.abs(wa - wb)) <= tol


@pytest.mark.parametrize("ext", ["step", "iges", "dxf"])
def test_round_trip_within_1e12(tmp_path, ext, quarter_circle, space_curve):
    # checks a rational quarter circle and a non-uniform 3-D cubic come back from STEP, IGES and DXF within
    # 1e-12, in order, with the names written
    path = tmp_path / f"curves.{ext}"
    report = hh.write([quarter_circle, space_curve], path, names=["arc", "spine"])
    assert report["curves"] == 2 and report["max_deviation"] == 0.0
    back = hh.read(path)
    assert len(back) == 2
    same_curve(back[0], quarter_circle)
    same_curve(back[1], space_curve)


def test_json_to_step_to_json_matches_the_cli(tmp_path, space_curve):
    # checks hh.read of a STEP file written by `hula convert` gives the curve `hula convert` reads back to
    # JSON, bit for bit, and both are the original within 1e-12
    src = tmp_path / "spine.json"
    hh.write(space_curve, src)
    hula("convert", src, "-o", tmp_path / "spine.step")
    hula("convert", tmp_path / "spine.step", "-o", tmp_path / "back.json")
    cli = hh.NurbsCurve.from_json(json.loads((tmp_path / "back.json").read_text()))
    ours = hh.read(tmp_path / "spine.step")
    assert len(ours) == 1
    assert np.array_equal(ours[0].control_points, cli.control_points)
    assert np.array_equal(ours[0].knots, cli.knots)
    same_curve(ours[0], space_curve)


def test_dxf_is_the_file_hula_convert_writes(tmp_path, quarter_circle):
    # checks hh.write's DXF is byte for byte the one `hula convert` writes from the same curve file
    src = tmp_path / "arc.json"
    src.write_text(quarter_circle.to_json())  # no name: the CLI names the curve after the file, "arc"
    hula("convert", src, "-o", tmp_path / "cli.dxf")
    hh.write(quarter_circle, tmp_path / "py.dxf", names=["arc"])
    assert (tmp_path / "py.dxf").read_bytes() == (tmp_path / "cli.dxf").read_bytes()


def test_json_file_round_trip_is_exact(tmp_path, space_curve):
    # checks a curve file written and read again is the same curve bit for bit
    hh.write(space_curve, tmp_path / "c.json")
    (back,) = hh.read(tmp_path / "c.json")
    assert np.array_equal(back.control_points, space_curve.control_points)
    assert np.array_equal(back.knots, space_curve.knots)


def test_svg_is_written_with_exact_cubic_paths(tmp_path, space_curve):
    # checks SVG output: one path per curve, exact for a cubic (deviation 0), and SVG is refused as input
    report = hh.write(space_curve, tmp_path / "c.svg")
    assert report["format"] == "svg" and report["curves"] == 1 and report["max_deviation"] == 0.0
    assert (tmp_path / "c.svg").read_text().count("<path") == 1
    with pytest.raises(hh.InvalidArgumentError):
        hh.read(tmp_path / "c.svg")


def test_bad_input_names_the_fault(tmp_path, space_curve):
    # checks an unknown extension, a wrong names length and a missing file raise the hulahoops errors
    with pytest.raises(hh.InvalidArgumentError) as e:
        hh.write(space_curve, tmp_path / "c.dwg")
    assert e.value.where["field"] == "path"
    with pytest.raises(hh.InvalidArgumentError) as e:
        hh.write([space_curve, space_curve], tmp_path / "c.dxf", names=["one"])
    assert e.value.where["field"] == "names"
    assert not (tmp_path / "c.dxf").exists()
    with pytest.raises(hh.IoError):
        hh.read(tmp_path / "missing.step")
