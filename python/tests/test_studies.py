# SPDX-License-Identifier: MIT
# The studies from dicts shaped like the study files: against `hula
# fair-knots` / `hula match-curvature` on the same files, bit for bit.
import json

import numpy as np
import pytest

import hulahoops as hh
from conftest import SOURCE, hula

STUDIES = SOURCE / "examples" / "studies"


def test_fair_knots_matches_cli_bit_for_bit():
    # checks the GA and deterministic fairing of thesis 7.4 example 1 against `hula fair-knots`, bit for bit
    path = STUDIES / "fair-knots-7.4-example1.json"
    setup = json.loads(path.read_text())
    r = hh.fair_knots(setup)
    cli = hula("fair-knots", path)
    assert r.energy == cli["energy"]
    assert np.array_equal(r.chord_length.parameters, cli["chord_length"]["parameters"])
    for method in ("ga", "deterministic"):
        if method in cli:
            assert np.array_equal(getattr(r, method).parameters, cli[method]["parameters"])
            assert getattr(r, method).energy == cli[method]["energy"]
            assert getattr(r, method).energy <= r.chord_length.energy
            # the run's report members are the CLI's (one writer, io::fairing_result_to_json)
            for key in ("evaluations", "rounds", "stopped", "termination", "message"):
                assert getattr(r, method)[key] == cli[method][key], key
    assert isinstance(r.chord_length.curve, hh.NurbsCurve)


def test_fair_knots_energy_map():
    # checks the energy map of thesis 7.3 example 1 is a (grid, grid) array whose minimum is the reported one
    setup = json.loads((STUDIES / "fair-knots-7.3-example1.json").read_text())
    setup["method"] = "none"
    r = hh.fair_knots(setup)
    e = r.map.energy
    assert e.shape == (r.map.k2.size, r.map.k1.size) == (40, 40)
    assert np.nanmin(e) == r.map.min_energy


def test_match_curvature_matches_cli_bit_for_bit():
    # checks thesis 8.2.1 example 1 (binary GA) against `hula match-curvature` on the same file, bit for bit
    path = STUDIES / "match-curvature-example1.json"
    r = hh.match_curvature(str(path))
    cli = hula("match-curvature", path)
    assert np.array_equal(r.best_points, cli["best_points"])
    # the distances of the best curve from the target profile (thesis 8.2.1: mean and max), both present
    assert set(cli["after"]) >= {"mean", "max"}
    assert r.after.mean == cli["after"]["mean"]
    assert r.after.max == cli["after"]["max"]
    assert r.keys() == list(cli.keys())


def test_study_errors_name_the_field():
    # checks a malformed setup raises the hulahoops error naming the field
    with pytest.raises(hh.Error) as e:
        hh.fair_knots({"format": "hula-study", "version": 1, "study": "fair-knots", "points": [[0, 0]]})
    assert "points" in e.value.message or e.value.where.get("field", "").startswith("points")
