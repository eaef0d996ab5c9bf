# SPDX-License-Identifier: MIT
# hulahoops.Document against the `hula doc` CLI (the independent C++ path,
# conftest.hula): the same file shows the same entities and history, a study
# run stores the same result curve bit for bit, failed changes leave the
# document as it was, and the writer lock holds between two writers.
import json
import shutil

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
