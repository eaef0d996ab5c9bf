# SPDX-License-Identifier: MIT
"""The thesis's curve studies (ch. 7 and 8) from Python.

A setup is the dict a study file holds (docs/formats.md "Study files"), e.g.
``{"format": "hula-study", "version": 1, "study": "fair-knots", "points":
[[0, 0], [40, 25], [80, -25], [120, 0]], "method": "both"}``; a path to a
study file works too. The result is a :class:`StudyResult`: attribute access
to the same fields ``hula fair-knots`` / ``hula match-curvature`` print, with
numeric lists as NumPy arrays and curves as :class:`~hulahoops.NurbsCurve`.

Both studies take ``callback(generation, best, evaluations)`` (``best`` the
generation's smallest energy or distance, ``evaluations`` counted across the
study's optimiser runs; returning True stops the study with its best so far)
and ``verbose`` (one progress line per generation on ``sys.stderr``). Ctrl-C
stops a study between generations and raises ``KeyboardInterrupt`` whose
``result`` attribute is the :class:`StudyResult` of the best so far.
"""

from __future__ import annotations

import json
import os
from typing import Any, Callable

import numpy as np

from . import _core
from .optimise import progress_function, raise_if_interrupted


class StudyResult:
    """A study's result: a read-only tree of fields (``result.ga.energy``,
    ``result["ga"]["energy"]``); numeric lists are float64 arrays."""

    def __init__(self, fields: dict[str, Any]) -> None:
        self._fields = {k: _wrap(v) for k, v in fields.items()}

    def __getattr__(self, name: str) -> Any:
        try:
            return self.__dict__["_fields"][name]
        except KeyError:
            raise AttributeError(name) from None

    def __getitem__(self, name: str) -> Any:
        return self._fields[name]

    def __contains__(self, name: str) -> bool:
        return name in self._fields

    def keys(self) -> list[str]:
        return list(self._fields)

    def __repr__(self) -> str:
        return f"StudyResult({', '.join(self._fields)})"


def _numeric(v: Any) -> bool:
    return isinstance(v, list) and len(v) > 0 and all(
        isinstance(e, (int, float)) and not isinstance(e, bool) or (isinstance(e, list) and _numeric(e)) for e in v)


def _wrap(v: Any) -> Any:
    if isinstance(v, dict):
        if v.get("format") == "hula-curve" or ("degree" in v and "knots" in v and "control_points" in v):
            return _core.NurbsCurve.from_json(v)
        return StudyResult(v)
    if _numeric(v):
        try:
            return np.asarray(v, dtype=np.float64)
        except ValueError:  # ragged
            return [_wrap(e) for e in v]
    if isinstance(v, list):
        return [_wrap(e) for e in v]
    return v


def _load(setup: Any) -> tuple[Any, str]:
    if isinstance(setup, (str, os.PathLike)):
        path = os.fspath(setup)
        with open(path, encoding="utf-8") as f:
            return json.load(f), os.path.dirname(os.path.abspath(path))
    return setup, os.getcwd()


def fair_knots(setup: Any, *, callback: Callable[[int, float, int], Any] | None = None,
               verbose: bool = False) -> StudyResult:
    """Knot-vector fairing (thesis 7.2-7.4): the parameters of the data points
    minimising the fairness energy of the interpolating cubic.

    Returns the fields of ``hula fair-knots``: ``energy`` (the energy's name),
    ``chord_length`` (chord-length parameters), ``given`` (if the setup
    has ``parameters``), ``ga`` and/or ``deterministic`` (per ``method``), each
    with ``parameters``, ``energy`` (∫κ² ds in 1/model units, or ∫(dκ/ds)² ds
    in 1/model units³, per ``energy``), ``bending``, ``variation``,
    ``curve``, and for optimisers ``improvement`` (1 - E/E_chord),
    ``evaluations``, ``convergence``; ``map`` with ``k1``, ``k2`` and the
    ``energy`` grid (NaN outside k1 < k2) when the setup asks for one.

    ``callback`` and ``verbose`` as the module says (each optimiser starts again at generation 0).

    Raises:
        KeyboardInterrupt: on Ctrl-C, with ``.result`` the StudyResult of the best so far.
    """
    data, _ = _load(setup)
    raw = _core.fair_knots(data, progress_function(callback, verbose, "fair-knots"))
    interrupt = raw.pop("interrupt", None)
    return raise_if_interrupted(interrupt, StudyResult(raw))


def fit(setup: Any, *, base: str | None = None, callback: Callable[[int, float, int], Any] | None = None,
        verbose: bool = False) -> StudyResult:
    """Scanned points to a class-A curve (thesis ch. 3; ``hula fit``): a "fit" study dict or file, e.g.
    ``{"format": "hula-study", "version": 1, "study": "fit", "points": [[x, y], ...], "class": "A"}``.

    Returns the fields ``hula fit`` prints (``tolerance``, ``strays``, ``before`` and ``after`` with their
    deviations, control points, inflections, curvature extrema and energies ...) and ``curve``, the
    faired :class:`~hulahoops.NurbsCurve` (the curve ``hula fit -o`` writes). ``base``: where a points file
    named in the setup is read from (default: the study file's directory, or the working directory).

    ``callback(generation, best, evaluations)`` and ``verbose`` follow the search: one generation per
    candidate curve fitted (``best`` its largest deviation of a kept point, ``evaluations`` the
    least-squares solves so far), then one last with the result (``after``'s ``max_deviation`` and
    ``fits``). The fit has no best so far to stop with: the callback's return value is not read; an
    exception it raises ends the fit and propagates.
    """
    data, where = _load(setup)
    return StudyResult(_core.fit(data, base or where, progress_function(callback, verbose, "fit")))


def match_curvature(setup: Any, *, method: str | None = None, base: str | None = None,
                    callback: Callable[[int, float, int], Any] | None = None, verbose: bool = False) -> StudyResult:
    """Curvature-profile matching (thesis 8.2.1): moves the free data points
    so the interpolating curve's curvature follows a target profile.

    Args:
        setup: a match-curvature study dict or the path of a study file.
        method: ``"ga"``, ``"hybrid"`` or ``"direct"``, overriding the setup's.
        base: directory relative file names in the setup resolve against
            (default: the study file's directory, or the working directory).
        callback, verbose: as the module says (re-centred rounds start again at generation 0).

    Returns the fields of ``hula match-curvature``'s JSON (``best``,
    ``distances``, ``curve`` ...), numeric lists as arrays.

    Raises:
        KeyboardInterrupt: on Ctrl-C, with ``.result`` the StudyResult of the best so far.
    """
    data, where = _load(setup)
    raw = _core.match_curvature(data, base or where, method, progress_function(callback, verbose, "match-curvature"))
    interrupt = raw.pop("interrupt", None)
    return raise_if_interrupted(interrupt, StudyResult(raw))
