# SPDX-License-Identifier: MIT
# Type stubs of hulahoops (docs/python.md). Units: coordinates in model units,
# curvature and torsion in 1/model units, t the curve's own parameter, s arc length.
import os
from typing import Any, Callable, Literal, Sequence, overload

import numpy as np
import numpy.typing as npt

from .errors import (CoincidentPointsError as CoincidentPointsError, Error as Error,
                     InvalidArgumentError as InvalidArgumentError, InvalidDegreeError as InvalidDegreeError,
                     InvalidKnotsError as InvalidKnotsError, InvalidOptionError as InvalidOptionError,
                     InvalidWeightError as InvalidWeightError, IoError as IoError,
                     NonFiniteInputError as NonFiniteInputError, NumericalFailureError as NumericalFailureError,
                     OutOfDomainError as OutOfDomainError, ParseError as ParseError,
                     ScaleOutOfRangeError as ScaleOutOfRangeError, TooFewPointsError as TooFewPointsError)
from .errors import DocumentCorruptError as DocumentCorruptError, DocumentLockedError as DocumentLockedError
from .errors import HelperFailureError as HelperFailureError, StorageFullError as StorageFullError
from .errors import UnsupportedError as UnsupportedError
from .optimise import (OptimiseResult as OptimiseResult, Problem as Problem, builtin_problem as builtin_problem,
                       evaluate_builtin as evaluate_builtin, from_pygmo as from_pygmo, optimise as optimise)
from .document import Document as Document
from .studies import StudyResult as StudyResult, fair_knots as fair_knots, match_curvature as match_curvature

ArrayLike = npt.ArrayLike
Array = npt.NDArray[np.float64]
__version__: str

DomainPolicy = Literal["strict", "clamp", "extrapolate"]
SidePolicy = Literal["right", "left"]

class ClosestPoint:
    """The closest point of a curve to a query point."""
    @property
    def t(self) -> float: ...
    @property
    def point(self) -> Array:
        """C(t), model units, shape (3,)."""
    @property
    def distance(self) -> float:
        """|C(t) - P|, model units."""

class NurbsCurve:
    """An immutable, validated NURBS curve of any degree >= 1, planar (dimension 2) or spatial (3)."""
    def __init__(self, degree: int, knots: ArrayLike, control_points: ArrayLike,
                 weights: ArrayLike | None = None) -> None:
        """knots: the full (clamped or not) non-decreasing knot vector, n + degree + 1 values.
        control_points: (n, 2) or (n, 3) in model units. weights: n positive finite numbers, or None.
        Raises InvalidKnotsError, InvalidDegreeError, InvalidWeightError, NonFiniteInputError naming the entry."""
    @property
    def degree(self) -> int: ...
    @property
    def dimension(self) -> int: ...
    @property
    def is_rational(self) -> bool: ...
    @property
    def knots(self) -> Array: ...
    @property
    def control_points(self) -> Array:
        """(n, dimension), model units (a copy)."""
    @property
    def weights(self) -> Array | None: ...
    @property
    def domain(self) -> tuple[float, float]: ...
    def __call__(self, t: ArrayLike, *, domain: DomainPolicy = "strict", side: SidePolicy = "right",
                 out: Array | None = None) -> Array:
        """Points C(t), shape t.shape + (dimension,), model units. Vectorised in C++, GIL released.
        domain: "strict" raises OutOfDomainError naming the index of the first t outside the domain;
        "clamp" evaluates at the nearest end; "extrapolate" continues the end pieces.
        side: one-sided limit at knots of reduced continuity. out: a C-contiguous float64 array of shape
        t.shape + (3,) to write into (always 3 columns, no allocation)."""
    def derivatives(self, t: ArrayLike, order: int, *, domain: DomainPolicy = "strict",
                    side: SidePolicy = "right") -> Array:
        """C, C', ..., C^(order) with respect to t, shape t.shape + (order + 1, dimension)."""
    def insert_knot(self, u: float, times: int = 1) -> NurbsCurve:
        """The same curve with u inserted `times` times (Boehm; The NURBS Book A5.1)."""
    def refine(self, knots: ArrayLike) -> NurbsCurve: ...
    def elevate(self, times: int = 1) -> NurbsCurve:
        """The same curve with degree + times (The NURBS Book A5.9)."""
    def reduce_degree(self, tolerance: float) -> dict[str, Any]:
        """Degree − 1 within tolerance (non-rational curves): {"curve", "error_bound" (max change bound),
        "bezier_bound" (the per-piece part)}; NumericalFailureError naming tolerance when it cannot be met."""
    def to_law(self) -> dict[str, Any]:
        """The curve written out as an exact law of t (`hula edit to-law`): {"law" (a Law), "expression", "spans",
        "degree", "max_difference", "expression_length"}."""
    def split(self, t: float) -> tuple[NurbsCurve, NurbsCurve]:
        """The pieces on [a, t] and [t, b], each clamped at t."""
    def reverse(self) -> NurbsCurve: ...
    def reparameterise(self, start: float, end: float) -> NurbsCurve: ...
    def arc_length(self, start: float | None = None, end: float | None = None, *,
                   tolerance: float = 1e-12) -> float:
        """Length between parameters (default the whole domain), model units, relative tolerance."""
    def parameter_at_length(self, s: float, *, tolerance: float = 1e-12) -> float:
        """The parameter t at arc length s from the domain start."""
    def closest_point(self, point: ArrayLike) -> ClosestPoint: ...
    def to_json(self) -> str:
        """The curve file text (docs/formats.md "Curve files")."""
    @staticmethod
    def from_json(document: str | dict[str, Any]) -> NurbsCurve:
        """A curve file's text or dict; interpolated and law kinds are resolved to NURBS."""
    @staticmethod
    def load(path: str) -> NurbsCurve: ...
    def save(self, path: str) -> None:
        """Writes the curve file atomically."""

def interpolate(points: ArrayLike, *, start: str | ArrayLike = "natural", end: str | ArrayLike = "natural",
                parameterisation: Literal["chord", "uniform", "centripetal", "foley"] = "chord",
                parameters: ArrayLike | None = None, closed: bool = False) -> NurbsCurve:
    """The C2 cubic spline through (n, 2) or (n, 3) points (thesis 5.5, 7.1).
    start/end: "natural", "bessel", "not-a-knot", "occt", or a tangent vector dC/dt (t in [0, 1]).
    parameters: explicit data parameters (increasing, from 0 to 1) instead of the parameterisation.
    closed: the periodic spline back to the first point, C2 at the closure (start/end unused; parameters then
    has n + 1 values, the last the closure's)."""

def read_points(path: str) -> Array:
    """The points of a point file as an (n, 2) or (n, 3) array: JSON, or lines of 2 or 3 numbers separated by
    whitespace, commas or semicolons, with header lines (an airfoil's name) and # comments; Selig and Lednicer
    airfoil files (docs/formats.md "Point files"). Errors name the file, the line and the separator."""

def analyse(curve: NurbsCurve | dict[str, Any], samples: int = 100, *, at: ArrayLike | None = None,
            by: str = "parameter", arc_lengths: bool = False, bishop: bool = False, fins: list[str] = ...,
            fin_scale: float | None = None, fin_density: int = 0, features: bool = False) -> dict[str, Any]:
    """The curve's analysis (diffgeom::analyse_curve, as `hula analyse` and POST .../analysis give it;
    docs/formats.md "Curve analysis"): t, s (arc lengths, by arc length or with arc_lengths), points (n, 3),
    frames {T, N, B} (n, 3), curvature, torsion, curvature_derivative, speed (n,), bishop {U, V} (with bishop),
    fins [{kind, scale, t, base, tip}], planarity {planar, normal, max_deviation, tolerance} and, with
    features, {inflections, curvature_extrema, torsion_extrema, knots, curvature_monotonicity,
    maximum_curvature}. Undefined values are NaN. `curve` is a NurbsCurve or a curve file as a dict."""

class NurbsFit:
    @property
    def curve(self) -> NurbsCurve: ...
    @property
    def max_deviation(self) -> float: ...
    @property
    def segments(self) -> int: ...
    @property
    def converged(self) -> bool: ...

class IntrinsicCurve:
    """A curve integrated from its natural equations, parameterised by arc length s in [0, length]."""
    @property
    def length(self) -> float: ...
    @property
    def method(self) -> str: ...
    @property
    def tolerance(self) -> float: ...
    def __call__(self, s: ArrayLike) -> Array:
        """Positions, shape s.shape + (3,); OutOfDomainError outside [0, length]."""
    def frames(self, s: ArrayLike) -> dict[str, Array]:
        """s, position, T, N, B (s.shape + (3,)), kappa, tau (s.shape)."""
    def to_nurbs(self, tolerance: float = 1e-9) -> NurbsFit:
        """A quintic NURBS within `tolerance` model units of the curve."""

def reconstruct(kappa: Law | str | float, tau: Law | str | float = 0.0, *, length: float,
                point: ArrayLike = ..., tangent: ArrayLike = ..., normal: ArrayLike = ...,
                tolerance: float = 1e-10, parameter: str = "s") -> IntrinsicCurve:
    """The curve with curvature κ(s) and torsion τ(s) (1/model units) for s in [0, length]
    (thesis 8.2.2), starting at `point` with unit tangent and normal (defaults: origin, +x, +y).
    τ ≡ 0 gives a planar curve with signed κ (eq. 34); otherwise Frenet–Serret is integrated."""

def intersect(a: NurbsCurve, b: NurbsCurve | None = None, *, tolerance: float | None = None) -> dict[str, Any]:
    """Where curves a and b meet, or with b omitted where a meets itself (docs/formats.md "Intersection
    results"): {"tolerance", "points": [{"s", "t", "point", "distance", "angle", "kind"}], "overlaps":
    [{"s": [s0, s1], "t": [t0, t1], "start", "end"}]}; kind is "crossing" or "tangent". tolerance:
    curves closer than this (model units, default 1e-6) meet."""

def distance(a: NurbsCurve, b: NurbsCurve, *, tolerance: float | None = None) -> dict[str, Any]:
    """The smallest distance between a and b: {"distance", "s", "t", "point_a", "point_b"}."""

def offset(curve: NurbsCurve | dict[str, Any] | str | os.PathLike[str], distance: float, *,
           tolerance: float | None = None, trim: bool = True) -> dict[str, Any]:
    """Planar offset of a plane curve by `distance` (model units, positive to the left of the direction of
    travel; docs/formats.md "Offset results"): {"distance", "tolerance", "exact", "deviation", "raw" (curve
    file: a law curve when the input is one), "cusps": [t], "loops": [{"s", "t", "point", "angle"}], "trimmed":
    [{"spans": [[t0, t1]], "closed", "curve"}]}. tolerance: of the offset's NURBS (default 1e-6)."""

def helical_offset(curve: NurbsCurve | dict[str, Any] | str | os.PathLike[str], distance: str, *, twist: str = "0",
                   frame: Literal["frenet", "bishop"] = "frenet", tolerance: float | None = None) -> dict[str, Any]:
    """Helical offset C + d (cos θ U + sin θ V) (thesis 6.5.2) with d and θ law texts of the curve parameter and
    {U, V} the Frenet {N, B} or the Bishop frame: {"frame", "distance", "twist", "tolerance", "exact",
    "deviation", "plane_normal" (a plane curve's Bishop frame), "curve" (curve file; a law curve when exact)}."""

def orthotomic(curve: NurbsCurve | dict[str, Any] | str | os.PathLike[str], pole: Sequence[float], *, k: float = 2.0,
               tolerance: float | None = None) -> dict[str, Any]:
    """K-orthotomic P + K (foot of the perpendicular from P on the tangent − P) (thesis 6.3.2; K = 2 the
    orthotomic, 1 the pedal): {"mapping", "pole", "k", "tolerance", "exact", "deviation", "curve"}."""

def hermite_frenet(document: dict[str, Any]) -> NurbsCurve:
    """The C3 septic Hermite curve through Frenet handles (docs/formats.md "Frenet handle files"):
    {"handles": [{"point", "tangent" (dC/dt), "normal", "curvature", "torsion"}], "parameters"?}; at every
    handle the curve has that tangent, curvature κ with normal N, and torsion τ."""

def polar_map(curve: NurbsCurve | dict[str, Any] | str | os.PathLike[str], centre: Sequence[float], *,
              radius: float = 1.0, tolerance: float | None = None) -> dict[str, Any]:
    """Polar map of a plane curve about the circle (centre, radius): the poles of its tangent lines, where its
    inflections are cusps (thesis 6.3.2): {"mapping", "centre", "radius", "tolerance", "exact", "deviation",
    "curve"}."""

class Law:
    """A law expression (docs/formats.md "Law expressions") of named parameters."""
    def __init__(self, text: str, parameters: Sequence[str] = ("t",)) -> None:
        """Raises ParseError with where = {"line", "column"} of the fault."""
    @property
    def parameters(self) -> list[str]: ...
    @property
    def dimension(self) -> int:
        """1 for scalar laws, 2 or 3 for vector laws."""
    @property
    def text(self) -> str: ...
    def __call__(self, *args: ArrayLike, **kwargs: ArrayLike) -> Any:
        """Values at broadcast parameter arrays: a float for scalar inputs, else an array of the broadcast
        shape (+ (dimension,) for vector laws). Undefined values (log of a negative number...) are NaN."""
    def derive(self, parameter: str | None = None, order: int = 1) -> Law:
        """The exact symbolic derivative."""
    def integrate(self, a: float, b: float, *, parameter: str | None = None,
                  relative_tolerance: float = 1e-12) -> float:
        """∫_a^b of a scalar law (adaptive Gauss–Kronrod, split at singularities; tanh-sinh at an
        integrable singular end, exp-sinh / sinh-sinh for a or b = ±inf); nan when divergent."""
    def antiderivative(self, parameter: str | None = None) -> Law | None:
        """A closed-form F with F' = self (substitution, by parts, rational, atan/asin forms, trigonometric
        powers; docs/modules/law.md), or None when no rule applies."""
    def roots(self, a: float, b: float, *, parameter: str | None = None) -> Array:
        """All roots of a scalar law in [a, b], increasing."""
