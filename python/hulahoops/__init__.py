# SPDX-License-Identifier: MIT
"""hulahoops: free-form curves for CAD in Python (docs/python.md).

Geometry:
    NurbsCurve        a validated NURBS curve; ``curve(t)``, ``curve.derivatives(t, n)``
                      vectorised over NumPy arrays; knot insertion, elevation,
                      split, arc length, closest point, JSON load/save.
    interpolate       cubic spline through points (thesis 5.5, 7.1).
    approximate       B-spline within a tolerance of points, or least squares with n control points.
    clothoid_g1, clothoid_g2   clothoids between end points with tangent angles (and curvatures).
    clothoid_spline, biarc     G1 / G2 clothoid and biarc splines through points (open or closed); one biarc.
    Law               law expressions: parse, evaluate, derive, integrate, roots.
    analyse           κ, τ, T, N, B, speed, fins along a curve (thesis ch. 6).
    reconstruct       a curve from its natural equations κ(s), τ(s) (thesis 8.2.2).
    intersect         where two curves (or one curve with itself) meet; distance: how far apart.
    offset            planar offset of a plane curve, cusps and loops trimmed;
                      helical_offset: winding around a curve (thesis 6.5.2).
    orthotomic        K-orthotomic about a pole; polar_map: poles of the tangents (thesis 6.3.2).
    hermite_frenet    a C3 curve through handles fixing tangent, curvature, normal and torsion.
Exchange:
    read, write       curve files by extension: JSON, STEP, IGES, DXF (SVG written only), as
                      ``hula convert`` reads and writes them.
    exchange_helper   the STEP/IGES helper used (the one the package ships, in a wheel).
Optimisation:
    optimise, Problem, from_pygmo   Flexo GAs and NSGA-II with NumPy objectives.
Studies:
    fair_knots, match_curvature, fit   the thesis's curve studies from study dicts.
Errors:
    Error and its subclasses (errors.py), with code, message and where.

Units: coordinates are model units (mm in the thesis's examples); curvature
and torsion are in 1/model units; parameters t are the curve's own.
"""

from __future__ import annotations

from . import _core
from .errors import (CoincidentPointsError, Error, InvalidArgumentError, InvalidDegreeError, InvalidKnotsError,
                     InvalidOptionError, InvalidWeightError, IoError, NonFiniteInputError, NumericalFailureError,
                     OutOfDomainError, ParseError, ScaleOutOfRangeError, TooFewPointsError)
from .errors import DocumentCorruptError, DocumentLockedError, HelperFailureError, StorageFullError, UnsupportedError
from .document import Document
from .optimise import OptimiseResult, Problem, builtin_problem, evaluate_builtin, from_pygmo, optimise
from .studies import StudyResult, fair_knots, fit, match_curvature

__version__: str = _core.__version__
NurbsCurve = _core.NurbsCurve
ClosestPoint = _core.ClosestPoint
IntrinsicCurve = _core.IntrinsicCurve
NurbsFit = _core.NurbsFit
Law = _core.Law
interpolate = _core.interpolate
approximate = _core.approximate
clothoid_g1 = _core.clothoid_g1
clothoid_g2 = _core.clothoid_g2
clothoid_spline = _core.clothoid_spline
biarc = _core.biarc
read_points = _core.read_points
analyse = _core.analyse
reconstruct = _core.reconstruct
intersect = _core.intersect
distance = _core.distance
offset = _core.offset
helical_offset = _core.helical_offset
orthotomic = _core.orthotomic
polar_map = _core.polar_map
hermite_frenet = _core.hermite_frenet
read = _core.read
write = _core.write
exchange_helper = _core.exchange_helper

__all__ = [
    "NurbsCurve", "ClosestPoint", "IntrinsicCurve", "NurbsFit", "Law", "interpolate", "approximate", "clothoid_g1",
    "clothoid_g2", "clothoid_spline", "biarc", "read_points",
    "analyse",
    "reconstruct", "intersect", "distance", "offset", "helical_offset", "orthotomic", "polar_map", "hermite_frenet",
    "read", "write", "exchange_helper",
    "optimise", "Problem", "OptimiseResult", "from_pygmo", "builtin_problem", "evaluate_builtin",
    "fair_knots", "fit", "match_curvature", "StudyResult", "Document",
    "Error", "InvalidArgumentError", "NonFiniteInputError", "TooFewPointsError", "CoincidentPointsError",
    "InvalidKnotsError", "InvalidDegreeError", "InvalidWeightError", "OutOfDomainError", "InvalidOptionError",
    "ParseError", "IoError", "NumericalFailureError", "ScaleOutOfRangeError", "UnsupportedError",
    "HelperFailureError", "DocumentLockedError", "DocumentCorruptError", "StorageFullError",
]
