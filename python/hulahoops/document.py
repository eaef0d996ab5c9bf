# SPDX-License-Identifier: MIT
"""The curve document: a ``.hula`` file of labelled curves with undo (the Oli layer).

A :class:`Document` is what ``hula doc`` edits (docs/cli.md, "hula doc"):
entities under stable integer labels, their attributes, a persistent undo
history. Every change is one transaction, committed to the file when the call
returns; a change that fails raises the :class:`hulahoops.Error` of its code
and leaves the document (and the file) exactly as it was.

Open read-write, a document holds the file's writer lock until :meth:`close`
(or the end of a ``with`` block); a second writer is refused.
"""

from __future__ import annotations

import json
import os
from typing import Any, Callable, Sequence

import numpy as np

from . import _core
from .optimise import progress_function, raise_if_interrupted


def _curve_value(curve: Any) -> Any:
    """A NurbsCurve, a dict in the curve-file format, or a path, as the binding takes them (no JSON text)."""
    if isinstance(curve, (_core.NurbsCurve, dict, str, os.PathLike)):
        return curve
    raise TypeError(f"curve must be a NurbsCurve, a dict or a path, not {type(curve).__name__}")


class Document:
    """A ``.hula`` curve document. Use :meth:`create` or :meth:`open`."""

    def __init__(self, core: Any) -> None:
        self._doc = core

    @classmethod
    def create(cls, path: str | os.PathLike[str], *, backend: str = "native", force: bool = False) -> Document:
        """Creates a new empty document file. ``backend`` is the geometry kernel, "native" or "occt".

        Raises IoError if the file exists (unless ``force``), InvalidOptionError for an unknown backend."""
        return cls(_core.Document.create(os.fspath(path), backend, force))

    @classmethod
    def open(cls, path: str | os.PathLike[str], *, read_only: bool = False) -> Document:
        """Opens a document file (read-only: no lock, no change allowed).

        Raises IoError naming the file if it is missing, locked by another writer, corrupt or newer."""
        return cls(_core.Document.open(os.fspath(path), read_only))

    def close(self) -> None:
        """Releases the file (and its writer lock); further calls raise InvalidArgumentError."""
        self._doc.close()

    def __enter__(self) -> Document:
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    @property
    def revision(self) -> int:
        """The number of the last committed transaction (0 for a new document)."""
        return self._doc.revision

    @property
    def backend(self) -> str:
        """The geometry kernel recorded in the document, "native" or "occt"."""
        return self._doc.backend

    @property
    def can_undo(self) -> bool:
        return self._doc.can_undo

    @property
    def can_redo(self) -> bool:
        return self._doc.can_redo

    def labels(self) -> list[int]:
        """The labels of the entities, ascending."""
        return list(self._doc.labels())

    def add(self, curve: Any, *, name: str = "") -> int:
        """Adds a curve (a NurbsCurve, a curve-file dict or a curve file's path); returns its new label."""
        return self._doc.add_curve(_curve_value(curve), name)

    def add_points(self, points: Any, *, name: str = "") -> int:
        """Adds a point set and returns its new label: N × 2 or N × 3 numbers (e.g. a NumPy array), or
        a point file's path (any point file: whitespace, comma or semicolon columns, airfoil .dat files)."""
        if isinstance(points, (str, os.PathLike)):
            points = _core.read_points(os.fspath(points))
        rows = [[float(v) for v in p] for p in points]
        return self._doc.add_points(rows, name)

    def show(self, label: int) -> dict[str, Any]:
        """The entity as ``hula doc show`` prints it: its curve-file JSON plus label, attributes, provenance."""
        return self._doc.show(label)

    def set(self, label: int, *, curve: Any = None, attribute: tuple[str, Any] | None = None,
            move_point: tuple[int, Any] | None = None) -> int:
        """Changes one thing of an entity and returns the new revision: exactly one of
        ``curve`` (replaces its construction data), ``attribute=(key, value)`` (a system attribute
        such as "name" or "colour", or a user key, with any JSON value), ``move_point=(index, (x, y, z))``
        (one control or data point, in model units)."""
        given = sum(x is not None for x in (curve, attribute, move_point))
        if given != 1:
            raise TypeError(f"give exactly one of curve, attribute, move_point (got {given})")
        if curve is not None:
            return self._doc.set_curve(label, _curve_value(curve))
        if attribute is not None:
            key, value = attribute
            return self._doc.set_attribute(label, key, value)
        index, to = move_point  # type: ignore[misc]
        p = [float(v) for v in to]
        if len(p) not in (2, 3):
            raise TypeError(f"move_point's point has {len(p)} coordinates, expected 2 or 3")
        return self._doc.move_point(label, index, p[0], p[1], p[2] if len(p) == 3 else 0.0)

    def remove(self, label: int) -> int:
        """Removes an entity (its label is never reused); returns the new revision."""
        return self._doc.remove(label)

    def undo(self) -> int:
        """Undoes the last transaction; returns the new revision. Raises InvalidArgumentError if none."""
        return self._doc.undo()

    def redo(self) -> int:
        """Redoes the last undone transaction; returns the new revision. Raises InvalidArgumentError if none."""
        return self._doc.redo()

    def history(self) -> list[dict[str, Any]]:
        """The undo steps: ``[{"revision", "name", "time", "changed": [labels], "applied"}]``."""
        return self._doc.history()

    def run(self, study: Any, *, base: str | os.PathLike[str] | None = None,
            callback: Callable[[int, Any, int], Any] | None = None, verbose: bool = False) -> dict[str, Any]:
        """Runs a study (a study-file dict, or a study file's path) whose curves may name entity labels,
        stores it with its result curves, and returns ``hula doc run``'s result (with ``cancelled``,
        ``study_label``, ``result_labels``, ``revision``). Relative file names in the study are read from
        ``base`` (default: the study file's directory, or the current directory for a dict).

        ``callback(generation, best, evaluations)`` is called after each generation of the study's
        optimisers (a true return stops the run with its best so far); ``verbose`` prints one progress
        line per generation on stderr. Ctrl-C stops the run between generations, stores the best so far
        as ``hula doc run`` does (``cancelled`` True) and raises ``KeyboardInterrupt`` whose ``result`` is
        that stored run's result."""
        if isinstance(study, (str, os.PathLike)):
            with open(study, encoding="utf-8") as f:
                setup = json.load(f)
            where = os.path.dirname(os.path.abspath(study))
        else:
            setup, where = study, os.getcwd()
        result = self._doc.run(setup, os.fspath(base) if base is not None else where,
                               progress_function(callback, verbose, "doc run"))
        return raise_if_interrupted(result.pop("interrupt", None), result)

    def export(self, labels: int | Sequence[int], path: str | os.PathLike[str], *,
               format: str | None = None) -> dict[str, Any]:
        """Writes entities to a file as ``hula doc export`` and ``hula convert`` write it, the format from
        the extension or ``format`` ("json", "step", "step-ap214", "step-ap242", "iges", "dxf", "svg"):
        JSON keeps every entity, the others the curves with their names, colours and layers (point sets
        and studies counted in ``skipped``). Returns ``{"format", "curves", "skipped", "max_deviation",
        "warnings"}``. STEP and IGES are written by the ``hula-exchange`` helper (Open CASCADE)."""
        ls = [labels] if isinstance(labels, int) else list(labels)
        return self._doc.export_file(ls, os.fspath(path), format)

    def import_(self, path: str | os.PathLike[str], *, format: str | None = None) -> dict[str, Any]:
        """Adds the entities of a file (JSON curve or document file, STEP, IGES, DXF; the format from the
        extension or ``format``) with the names, colours and layers it gives, as ``hula convert`` reads
        it. Returns ``{"labels", "format", "warnings", "revision"}``."""
        return self._doc.import_file(os.fspath(path), format)

    # Constraints stored with a curve (docs/modules/oli.md "Constraints"): dicts in the form `hula doc
    # show` prints under "constraints", e.g. {"kind": "pass-through", "point": [x, y, z], "tolerance": 1e-6},
    # {"kind": "end-tangent", "end": "start", "direction": [1, 0, 0]}, {"kind": "end-curvature", "end":
    # "end", "value": 0.1}, {"kind": "fixed-length", "value": 50}.

    def constraints(self, label: int) -> list[dict[str, Any]]:
        """The constraints stored with curve ``label``, in order (as ``show(label)["constraints"]``)."""
        return self._doc.constraints(label)

    def add_constraint(self, label: int, constraint: dict[str, Any]) -> int:
        """Appends one constraint to curve ``label``; returns the new revision. Raises ParseError naming
        the member for a malformed dict, InvalidArgumentError for a zero direction, a negative curvature,
        a length or tolerance <= 0, or an entity that is not a curve (the document is then unchanged)."""
        return self._doc.add_constraint(label, constraint)

    def remove_constraint(self, label: int, index: int) -> int:
        """Removes constraint ``index`` of curve ``label``; returns the new revision."""
        return self._doc.remove_constraint(label, index)

    def set_constraints(self, label: int, constraints: Sequence[dict[str, Any]]) -> int:
        """Replaces every constraint of curve ``label`` (``[]`` removes them all); returns the new revision."""
        return self._doc.set_constraints(label, list(constraints))

    def check_constraints(self, label: int) -> list[dict[str, Any]]:
        """Each stored constraint's residual on the curve: ``[{"index", "kind", "residual", "satisfied"}]``
        (residual NaN and not satisfied where it is undefined)."""
        return self._doc.check_constraints(label)

    # Design variables (docs/modules/oli.md "Variables"): a list of selections, each a dict
    # {"label": L, "kind": "control-points" | "weights" | "interior-knots" | "data-points" |
    # "end-tangents" | "law-constants", "indices": [...] (default all), "axes": "xyz" (points and
    # tangents), "bounds": {"mode": "relative" | "absolute", "lower": -1, "upper": 1}}.

    def variables(self, selections: Sequence[dict[str, Any]]) -> dict[str, Any]:
        """The selected parameters' ``names`` ("3.control-points[2].y"), current ``values`` and resolved
        ``lower`` / ``upper`` bounds (float64 arrays). Raises InvalidArgumentError naming selections[i] for
        a missing label, a kind the entity lacks, an index out of range, bad axes or bounds."""
        return self._doc.variables(list(selections))

    def set_variables(self, selections: Sequence[dict[str, Any]], values: Any) -> int:
        """Writes ``values`` (one per variable, in ``variables(selections)["names"]`` order) into the
        entities in one transaction; returns the new revision. A value that makes a curve invalid (knots
        out of order, a weight <= 0) raises and leaves the document unchanged."""
        return self._doc.set_variables(list(selections), np.asarray(values, dtype=np.float64))
