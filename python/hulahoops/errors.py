# SPDX-License-Identifier: MIT
"""Errors raised by hulahoops.

Every invalid input raises a subclass of :class:`Error` named after its code
(docs/errors.md): ``InvalidArgumentError``, ``ParseError``, ``OutOfDomainError``
and so on. Each carries

* ``code``: the stable code name, e.g. ``"InvalidKnots"``;
* ``message``: what was wrong, naming the input and its value;
* ``where``: a dict locating the fault, with any of ``field``, ``index``,
  ``component``, ``line``, ``column`` (e.g. ``{"field": "knots", "index": 7}``).

Undefined quantities (torsion where the curvature vanishes) are not errors:
they are NaN in the result arrays, as documented per function.
"""

from __future__ import annotations

from typing import Any


class Error(Exception):
    """Base class of every hulahoops error: ``code``, ``message``, ``where``."""

    def __init__(self, code: str, message: str, where: dict[str, Any] | None = None) -> None:
        super().__init__(f"{code}: {message}")
        self.code = code
        self.message = message
        self.where = dict(where or {})


class InvalidArgumentError(Error):
    """An argument is outside its documented range (wrong shape, unknown name)."""


class NonFiniteInputError(Error):
    """NaN or infinity in a number that must be finite."""


class TooFewPointsError(Error):
    """Fewer points than the operation needs."""


class CoincidentPointsError(Error):
    """Consecutive points coincide where a distance is needed."""


class InvalidKnotsError(Error):
    """Knot vector malformed (order, size, multiplicity)."""


class InvalidDegreeError(Error):
    """Degree < 1 or not below the number of control points."""


class InvalidWeightError(Error):
    """A rational weight is <= 0 or not finite."""


class OutOfDomainError(Error):
    """A parameter is outside the curve's domain."""


class InvalidOptionError(Error):
    """An option is out of range or unknown."""


class ParseError(Error):
    """Text (JSON, expression) cannot be parsed; ``where`` has line and column."""


class IoError(Error):
    """A file cannot be read or written."""


class NumericalFailureError(Error):
    """The computation overflowed or did not converge."""


class ScaleOutOfRangeError(Error):
    """Model coordinates too large or too small to handle."""


class UnsupportedError(Error):
    """The selected kernel backend has no such operation; ``where["field"]`` names it."""


class HelperFailureError(Error):
    """An isolated helper process (STEP/IGES exchange) crashed, hung or ran out of memory."""


class DocumentLockedError(IoError):
    """A document is open for writing elsewhere, or stayed busy past SQLite's timeout."""


class DocumentCorruptError(IoError):
    """A document file is truncated or corrupt."""


class StorageFullError(IoError):
    """The disk is full or a file-size limit was reached while writing a document."""


_BY_CODE: dict[str, type[Error]] = {
    "InvalidArgument": InvalidArgumentError,
    "NonFiniteInput": NonFiniteInputError,
    "TooFewPoints": TooFewPointsError,
    "CoincidentPoints": CoincidentPointsError,
    "InvalidKnots": InvalidKnotsError,
    "InvalidDegree": InvalidDegreeError,
    "InvalidWeight": InvalidWeightError,
    "OutOfDomain": OutOfDomainError,
    "InvalidOption": InvalidOptionError,
    "ParseError": ParseError,
    "IoError": IoError,
    "NumericalFailure": NumericalFailureError,
    "ScaleOutOfRange": ScaleOutOfRangeError,
    "Unsupported": UnsupportedError,
    "HelperFailure": HelperFailureError,
    "DocumentLocked": DocumentLockedError,
    "DocumentCorrupt": DocumentCorruptError,
    "StorageFull": StorageFullError,
}


def error_class(code: str) -> type[Error]:
    """The class raised for a code (Error itself for a code this version does not know)."""
    return _BY_CODE.get(code, Error)
