# SPDX-License-Identifier: MIT
# hulahoops.Document against the `hula doc` CLI (the independent C++ path,
# conftest.hula): the same file shows the same entities and history, a study
# run stores the same result curve bit for bit, failed changes leave the
# document as it was, and the writer lock holds between two writers.
import json
import shutil

import numpy as np

import pytest

import hulahoops as hh
from conftest import SOURCE, hula

SPINE = SOURCE / "examples" / "curves" / "spine.json"
POINTS = [[0, 0], [5, 20], [40, 0]]
# Thesis 8.2.1 Example 1 on a point-set entity with a small GA (as tests/oli/study_run_test.cpp).
STUDY = {"format": "hula-study", "version": 1, "study": "match-curvature", "seed": 5,
         "lower": [[0, 0], [30, 30], [0, 0]], "upper": [[0, 0], [35, 30], [0, 0]],
         "samples": 50, "method": "ga",
         "ga": {"algorithm": "binary", "population": 12, "generations": 6, "boost_start": 3, "boost_end": 5,
                "crossover_probability": 1.0, "mutation_probability": 0.01, "precision": 0.001},
         "points": {"entity": 1}, "target": {"of_points": {"entity": 1}, "mirror": True}}


def test_edits_undo_redo_match_the_cli(tmp_path):
    # checks the docs/cli.md `hula doc` walk-through done from Python leaves a file that `hula doc show`
    # and `hula doc history` read as the Python side reports it
    path = tmp_path / "part.hula"
    with hh.Document.create(path) as doc:
        assert doc.revision == 0 and doc.backend == "native"
        label = doc.add(json.loads(SPINE.read_text()), name="spine")
        assert label == 1 and doc.revision == 1
        assert doc.set(1, move_point=(1, (1, 2.5, 0))) == 2
        assert doc.set(1, attribute=("colour", "#ff0000")) == 3
        assert doc.undo() == 2 and doc.can_redo
        assert doc.redo() == 3
        assert doc.undo() == 2
        shown = doc.show(1)
        history = doc.history()
    assert shown["control_points"][1] == [1.0, 2.5, 0.0]
    assert shown["attributes"]["colour"] != "#ff0000"
    assert hula("doc", "show", path, 1) == shown
    cli = hula("doc", "history", path)
    applied = [{k: h[k] for k in ("revision", "name", "changed")} for h in history if h["applied"]]
    assert applied == [{k: h[k] for k in ("revision", "name", "changed")} for h in cli["transactions"]]
    assert [h["name"] for h in history if not h["applied"]] == ["set colour"]
    # Reopened, the undo history persists: the redo step is still there.
    with hh.Document.open(path) as doc:
        assert doc.redo() == 3 and doc.show(1)["attributes"]["colour"] == "#ff0000"


def test_failed_changes_raise_and_leave_the_document_unchanged(tmp_path):
    # checks invalid edits raise the Error subclass of their code, and neither revision nor entity moves
    path = tmp_path / "d.hula"
    with hh.Document.create(path) as doc:
        doc.add(SPINE, name="spine")
        before = doc.show(1)
        with pytest.raises(hh.Error) as e:
            doc.set(1, move_point=(99, (0, 0, 0)))
        assert "99" in e.value.message
        with pytest.raises(hh.Error):
            doc.set(1, move_point=(0, (float("nan"), 0, 0)))
        with pytest.raises(hh.InvalidArgumentError):
            doc.show(7)
        assert doc.revision == 1 and doc.show(1) == before
        doc.undo()
        with pytest.raises(hh.InvalidArgumentError):
            doc.undo()
        with pytest.raises(TypeError):
            doc.set(1)
    with pytest.raises(hh.InvalidArgumentError, match="closed"):
        doc.labels()
    assert hula("doc", "check", path)["ok"] is True


def test_second_writer_is_refused_until_close(tmp_path):
    # checks the file's writer lock: a second read-write open fails while the first is open, read-only works
    path = tmp_path / "lock.hula"
    first = hh.Document.create(path)
    with pytest.raises(hh.Error):
        hh.Document.open(path)
    with hh.Document.open(path, read_only=True) as reader:
        assert reader.labels() == []
    first.close()
    with hh.Document.open(path) as second:
        assert second.revision == 0


def test_run_stores_the_same_result_as_hula_doc_run(tmp_path):
    # checks a study run from Python stores the result curve `hula doc run` stores from the same file and study
    a, b = tmp_path / "a.hula", tmp_path / "b.hula"
    with hh.Document.create(a) as doc:
        assert doc.add_points(POINTS, name="data") == 1
    shutil.copyfile(a, b)
    study = tmp_path / "study.json"
    study.write_text(json.dumps(STUDY))
    with hh.Document.open(a) as doc:
        ran = doc.run(STUDY, base=tmp_path)
        curve = doc.show(ran["result_labels"][0])
    cli = hula("doc", "run", b, study)
    assert ran["result_labels"] == cli["result_labels"] and ran["study_label"] == cli["study_label"]
    assert hula("doc", "show", b, cli["result_labels"][0])["control_points"] == curve["control_points"]


LINE = {"kind": "nurbs", "degree": 1, "knots": [0, 0, 1, 1], "control_points": [[0, 0, 0], [10, 0, 0]]}


def test_constraints_are_stored_checked_and_shown_by_hula_doc(tmp_path):
    # checks constraints added from Python are what `hula doc show` prints, their residuals on the line
    # (0,0,0)-(10,0,0) are the closed forms (distance 3 to (5,3,0), |10 - 12| = 2, angle pi/2 between +x
    # and +y, |0 - 0.25| for a line's curvature), removal and undo restore the list, and bad constraints
    # are refused by name with the document unchanged
    path = tmp_path / "c.hula"
    with hh.Document.create(path) as doc:
        label = doc.add(LINE, name="line")
        assert doc.constraints(label) == []
        doc.add_constraint(label, {"kind": "pass-through", "point": [5, 3, 0], "tolerance": 1e-3})
        doc.add_constraint(label, {"kind": "fixed-length", "value": 12})
        doc.add_constraint(label, {"kind": "end-tangent", "end": "start", "direction": [0, 2, 0]})
        revision = doc.add_constraint(label, {"kind": "end-curvature", "end": "end", "value": 0.25})
        stored = doc.constraints(label)
        assert [c["kind"] for c in stored] == ["pass-through", "fixed-length", "end-tangent", "end-curvature"]
        checked = doc.check_constraints(label)
        assert [c["index"] for c in checked] == [0, 1, 2, 3]
        assert checked[0]["residual"] == pytest.approx(3, abs=1e-9) and not checked[0]["satisfied"]
        assert checked[1]["residual"] == pytest.approx(2, abs=1e-9)
        assert checked[2]["residual"] == pytest.approx(np.pi / 2, abs=1e-12)
        assert checked[3]["residual"] == pytest.approx(0.25, abs=1e-12)
        for bad, error in [({"kind": "fixed-length", "value": -1}, hh.InvalidArgumentError),
                           ({"kind": "pass-through"}, hh.ParseError),
                           ({"kind": "tangent", "end": "start"}, hh.ParseError),
                           ({"kind": "end-tangent", "end": "start", "direction": [0, 0, 0]}, hh.InvalidArgumentError)]:
            with pytest.raises(error):
                doc.add_constraint(label, bad)
        with pytest.raises(hh.InvalidArgumentError, match="index"):
            doc.remove_constraint(label, 4)
        assert doc.revision == revision and doc.constraints(label) == stored
        points = doc.add_points(POINTS)
        with pytest.raises(hh.Error):
            doc.add_constraint(points, {"kind": "fixed-length", "value": 1})
        with pytest.raises(hh.Error):
            doc.constraints(points)
        doc.remove_constraint(label, 1)
        assert [c["kind"] for c in doc.constraints(label)] == ["pass-through", "end-tangent", "end-curvature"]
        doc.undo()
        assert doc.constraints(label) == stored
        doc.set_constraints(label, [{"kind": "fixed-length", "value": 10}])
        assert doc.check_constraints(label)[0]["satisfied"]
    shown = hula("doc", "show", path, label)["constraints"]
    assert shown == [{"kind": "fixed-length", "value": 10.0, "tolerance": 1e-6}]


CURVE = {"kind": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.5, 1, 1, 1],
         "control_points": [[0, 0], [2, 3], [5, 3], [7, 0]]}


def test_variables_read_and_written_as_hula_doc_show_sees_them(tmp_path):
    # checks variables over control points (some indices, one axis, relative bounds) and the interior knot
    # (absolute bounds) read the stored values, writing them changes exactly those numbers (read back by
    # `hula doc show`), and a knot moved out of order or a bad selection is refused with nothing changed
    path = tmp_path / "v.hula"
    selections = [{"label": 1, "kind": "control-points", "indices": [1, 2], "axes": "y",
                   "bounds": {"mode": "relative", "lower": -0.5, "upper": 0.25}},
                  {"label": 1, "kind": "interior-knots", "bounds": {"mode": "absolute", "lower": 0.1, "upper": 0.9}}]
    with hh.Document.create(path) as doc:
        doc.add(CURVE)
        v = doc.variables(selections)
        assert v["names"] == ["1.control-points[1].y", "1.control-points[2].y", "1.interior-knots[0]"]
        assert v["values"].tolist() == [3, 3, 0.5]
        assert v["lower"].tolist() == [2.5, 2.5, 0.1] and v["upper"].tolist() == [3.25, 3.25, 0.9]
        revision = doc.set_variables(selections, [2.75, 3.125, 0.4])
        with pytest.raises(hh.Error):
            doc.set_variables(selections, [3, 3, 1.5])  # the interior knot past the end knot
        with pytest.raises(hh.Error):
            doc.set_variables(selections, [3, 3])
        for bad in [[{"label": 7, "kind": "control-points"}], [{"label": 1, "kind": "weights"}],
                    [{"label": 1, "kind": "control-points", "indices": [9]}],
                    [{"label": 1, "kind": "control-points", "axes": "z"}]]:
            with pytest.raises(hh.Error, match="selections\\[0\\]"):
                doc.variables(bad)
        with pytest.raises(hh.ParseError, match="selections\\[0\\].kind"):
            doc.variables([{"label": 1, "kind": "knots"}])
        assert doc.revision == revision
    shown = hula("doc", "show", path, 1)
    assert shown["control_points"] == [[0, 0], [2, 2.75], [5, 3.125], [7, 0]]
    assert shown["knots"] == [0, 0, 0, 0.4, 1, 1, 1]
