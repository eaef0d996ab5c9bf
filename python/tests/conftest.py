# SPDX-License-Identifier: MIT
# Shared fixtures of the hulahoops tests: the `hula` CLI, the other door to the
# same C++ libraries, whose results the binding's must equal bit for bit (its
# JSON prints doubles in shortest round-trip form): a check that both doors
# give one answer, not an independent reference (closed forms, Open CASCADE and
# published values are, in the tests that use them); and the thesis's example
# curves.
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

SOURCE = pathlib.Path(os.environ.get("HULA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
HULA = os.environ.get("HULA_BIN", str(SOURCE / "build" / "ci" / "apps" / "hula" / "hula"))


def hula(*args, check=True):
    """Runs the hula CLI and returns its JSON output."""
    r = subprocess.run([HULA, *map(str, args)], capture_output=True, text=True, timeout=300)
    if check and r.returncode != 0:
        raise AssertionError(f"hula {' '.join(map(str, args))} failed ({r.returncode}): {r.stderr}")
    return json.loads(r.stdout) if r.stdout.strip() else None


def numbers(values):
    """A comma-separated list that parses back to the same doubles (repr is shortest round-trip)."""
    return ",".join(repr(float(v)) for v in values)


@pytest.fixture
def quarter_circle():
    """The unit quarter circle as a rational quadratic (The NURBS Book ex. 7.1): |C(t)| = 1 exactly in theory."""
    import hulahoops as hh
    w = np.sqrt(0.5)
    return hh.NurbsCurve(2, [0, 0, 0, 1, 1, 1], [[1, 0], [1, 1], [0, 1]], weights=[1, w, 1])


@pytest.fixture
def space_curve():
    """A non-uniform cubic space curve with an interior double knot."""
    import hulahoops as hh
    knots = [0, 0, 0, 0, 0.3, 0.3, 0.7, 1, 1, 1, 1]
    points = [[0, 0, 0], [1, 2, 0.5], [3, 3, 1], [4, 1, 2], [6, 0, 1], [7, 2, 0], [9, 3, 1]]
    return hh.NurbsCurve(3, knots, points)
