# SPDX-License-Identifier: MIT
"""Flexo optimisation from Python (thesis ch. 2 and app. 2; docs/python.md).

A problem is one of

* :class:`Problem`: a vectorised objective ``f(X)`` taking an ``(n, d)`` array
  of points and returning an ``(n, k)`` array (objectives, then inequality
  constraints ``g <= 0``, then equality constraints ``h = 0``), or ``(n,)`` for
  a single objective; bounds as arrays;
* a pygmo user-defined problem, unchanged: any object with ``fitness(x)`` and
  ``get_bounds()`` (and optionally ``get_nobj``, ``get_nic``, ``get_nec``,
  ``batch_fitness``), pygmo's fitness order (objectives, equality, then
  inequality constraints) being converted;
* the name of a built-in test problem (``"sphere"``, ``"rastrigin"``,
  ``"schwefel"``, ``"zdt1"`` ... as ``hula optimise --problem``), evaluated in
  C++ without Python.

The C++ loops run with the GIL released; the objective is called once per
generation with the whole batch. An exception raised by the objective stops
the run and propagates unchanged (same type, same traceback).

Ctrl-C (SIGINT, a notebook's interrupt) stops a run between generations:
:func:`optimise` raises ``KeyboardInterrupt`` whose ``result`` attribute is
the :class:`OptimiseResult` of the best so far (termination ``"Cancelled"``).
The run goes on a worker thread while the calling thread checks Python's
signals every 20 ms, so the interrupt arrives as soon as the generation under
way ends (with a Python objective: once its call returns).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable

import sys

import numpy as np

from . import _core


class Problem:
    """A minimisation problem with a vectorised objective.

    Args:
        objective: ``f(X) -> F``, ``X`` of shape ``(n, d)`` (float64, a fresh
            array the function may keep), ``F`` of shape ``(n, k)`` with
            ``k = objectives + inequality + equality`` or ``(n,)`` when k = 1.
            NaN or infinity in a row marks that point failed (it ranks last).
        lower, upper: bounds, ``d`` finite numbers each, ``lower <= upper``.
        objectives: number of objectives (>= 1), all minimised.
        inequality: number of constraints ``g(x) <= 0``.
        equality: number of constraints ``h(x) = 0`` (met when ``|h| <= 1e-6``).
        name: shown in reports.

    A Problem is also a pygmo user-defined problem (``fitness``,
    ``get_bounds``, ``get_nobj``, ``get_nic``, ``get_nec``, ``batch_fitness``),
    so ``pygmo.problem(hulahoops.Problem(...))`` works.
    """

    def __init__(self, objective: Callable[[np.ndarray], Any], lower: Any, upper: Any, *, objectives: int = 1,
                 inequality: int = 0, equality: int = 0, name: str = "python") -> None:
        self.objective = objective
        self.lower = np.array(lower, dtype=np.float64).reshape(-1)
        self.upper = np.array(upper, dtype=np.float64).reshape(-1)
        self.objectives = int(objectives)
        self.inequality = int(inequality)
        self.equality = int(equality)
        self.name = name

    # pygmo's user-defined-problem interface.
    def fitness(self, x: Any) -> np.ndarray:
        """pygmo order: objectives, equality constraints, inequality constraints."""
        values = np.asarray(self.objective(np.asarray(x, dtype=np.float64).reshape(1, -1)), dtype=np.float64)
        return _flexo_to_pygmo(values.reshape(1, -1), self.objectives, self.inequality, self.equality)[0]

    def batch_fitness(self, dvs: Any) -> np.ndarray:
        """pygmo's batch form: decision vectors concatenated, fitness vectors concatenated."""
        X = np.asarray(dvs, dtype=np.float64).reshape(-1, self.lower.size)
        values = np.asarray(self.objective(X), dtype=np.float64).reshape(X.shape[0], -1)
        return _flexo_to_pygmo(values, self.objectives, self.inequality, self.equality).reshape(-1)

    def get_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        return self.lower.copy(), self.upper.copy()

    def get_nobj(self) -> int:
        return self.objectives

    def get_nic(self) -> int:
        return self.inequality

    def get_nec(self) -> int:
        return self.equality

    def get_name(self) -> str:
        return self.name


def _flexo_to_pygmo(values: np.ndarray, m: int, ni: int, ne: int) -> np.ndarray:
    return np.concatenate([values[:, :m], values[:, m + ni:m + ni + ne], values[:, m:m + ni]], axis=1)


def from_pygmo(udp: Any) -> Problem:
    """Wraps a pygmo user-defined problem as a :class:`Problem`.

    ``batch_fitness`` is used when the UDP has it (one call per generation);
    otherwise ``fitness`` is called once per point.
    """
    lower, upper = udp.get_bounds()
    m = int(udp.get_nobj()) if hasattr(udp, "get_nobj") else 1
    ni = int(udp.get_nic()) if hasattr(udp, "get_nic") else 0
    ne = int(udp.get_nec()) if hasattr(udp, "get_nec") else 0

    def objective(X: np.ndarray) -> np.ndarray:
        if hasattr(udp, "batch_fitness"):
            f = np.asarray(udp.batch_fitness(X.reshape(-1)), dtype=np.float64).reshape(X.shape[0], -1)
        else:
            f = np.array([np.asarray(udp.fitness(x), dtype=np.float64) for x in X]).reshape(X.shape[0], -1)
        # pygmo order (objectives, equality, inequality) to Flexo's (objectives, inequality, equality).
        return np.concatenate([f[:, :m], f[:, m + ne:m + ne + ni], f[:, m:m + ne]], axis=1)

    name = udp.get_name() if hasattr(udp, "get_name") else type(udp).__name__
    return Problem(objective, lower, upper, objectives=m, inequality=ni, equality=ne, name=name)


@dataclass
class OptimiseResult:
    """The outcome of :func:`optimise`.

    Attributes:
        x: best variables (single objective), shape ``(d,)``; None for NSGA-II.
        f: their objective values, shape ``(k_obj,)``; None for NSGA-II.
        violation: total constraint violation of ``x`` (0 = feasible).
        front_x, front_f: the final non-dominated set (NSGA-II), shapes
            ``(n, d)`` and ``(n, objectives)``; None for the GAs.
        population_x, population_f: NSGA-II's final population.
        hypervolume: the hypervolume of the front's feasible members against
            ``reference`` (several objectives: built-in problems 1.1 per
            objective, as ``hula optimise`` reports it; a Problem's with the
            ``reference`` option); None otherwise.
        reference: that reference point, shape ``(objectives,)``.
        best_per_generation, mean_per_generation: the convergence graph, one
            value per generation (generation 0 = the initial population);
            None for island runs.
        report: the run report exactly as ``hula optimise`` prints it under
            ``"report"``: termination (``"MaxGenerations"``, ``"TargetReached"``,
            ``"Converged"`` ...), message, generations, evaluations,
            failed_evaluations, seconds, seed, threads, algorithm, problem.
        islands: for island runs, one dict per island: seed, x, f, report,
            sent, received, accepted, its archive size (``archive``, NSGA-II:
            the island's external archive of non-dominated points, from which
            with the final populations the front is merged and thinned to at
            most islands x population) and its migration log
            (``migrations``: generation, from, received, accepted).
    """

    report: dict[str, Any]
    best_per_generation: np.ndarray | None = None
    mean_per_generation: np.ndarray | None = None
    islands: list[dict[str, Any]] | None = None
    x: np.ndarray | None = None
    f: np.ndarray | None = None
    violation: float = 0.0
    front_x: np.ndarray | None = None
    front_f: np.ndarray | None = None
    population_x: np.ndarray | None = None
    population_f: np.ndarray | None = None
    hypervolume: float | None = None
    reference: np.ndarray | None = None
    extra: dict[str, Any] = field(default_factory=dict)


def progress_function(callback: Callable[..., Any] | None, verbose: bool,
                      label: str) -> Callable[[int, Any, int], bool] | None:
    """The per-generation function given to the C++ loops: prints the progress line of ``verbose`` to
    stderr (``label: generation G, evaluations E, best B``), then calls ``callback(generation, best,
    evaluations)``; a true return from the callback stops the run. None when neither is asked for."""
    if callback is None and not verbose:
        return None

    def progress(generation: int, best: Any, evaluations: int) -> bool:
        if verbose:
            b = np.array2string(np.asarray(best), precision=6) if np.ndim(best) else f"{best:.6g}"
            print(f"{label}: generation {generation}, evaluations {evaluations}, best {b}", file=sys.stderr,
                  flush=True)
        return bool(callback(generation, best, evaluations)) if callback is not None else False

    return progress


def raise_if_interrupted(interrupt: BaseException | None, result: Any) -> Any:
    """Raises the signal handler's exception (KeyboardInterrupt) a run was stopped by, with ``result``
    (the best so far) as its ``result`` attribute; otherwise returns ``result``."""
    if interrupt is not None:
        interrupt.result = result
        raise interrupt
    return result


def optimise(problem: Any, algorithm: str = "ga-real", *, dimension: int = 0, objectives: int = 0,
             precision: Any = None, callback: Callable[[int, Any, int], Any] | None = None, verbose: bool = False,
             **options: Any) -> OptimiseResult:
    """Minimises a problem with a Flexo algorithm.

    Args:
        problem: a :class:`Problem`, a pygmo UDP, or a built-in problem name.
        algorithm: ``"ga-real"`` (SBX + polynomial mutation), ``"ga-binary"``
            (the thesis's binary GA: roulette, power boosting), ``"nsga2"``,
            ``"nelder-mead"`` (the deterministic downhill simplex from
            ``start``, default the centre of the bounds; one objective, no
            constraints; points outside the bounds rank worst) or one of
            pagmo2's through the adapter, ``"pagmo-<name>"`` with name
            ``cmaes``, ``de``, ``sade``, ``pso``, ``sga``, ``moead`` or
            ``nsga2`` (options ``population``, ``generations``, ``seed`` and
            ``wall_time`` only, read as ``hula optimise --algorithm
            pagmo-<name>`` reads them; pagmo runs its own loop, which Ctrl-C,
            ``wall_time`` and the callback's True stop before its next
            evaluation, with the best evaluation so far).
            All run through the same C++ entry as ``hula optimise``
            (``optim::solve``).
        dimension, objectives: for built-in problems (0 = the problem's default).
        precision: binary coding resolution in the variables' units (one number
            or one per variable); required by ``"ga-binary"``.
        **options: ``population`` (100), ``generations`` (100),
            ``max_evaluations``, ``seed`` (0), ``threads`` (built-in problems
            only; results never depend on it), ``target``,
            ``stagnation_generations``, ``wall_time`` (seconds), and per
            algorithm ``crossover_probability``, ``crossover_eta``,
            ``mutation_probability``, ``mutation_eta``, ``elites``,
            ``tournament_size``, ``boost_start``, ``boost_end``,
            ``selection`` (``"roulette"``/``"tournament"``), ``crossover``
            (``"single-point"``/``"uniform"``); the island model: ``islands``
            (K populations on threads, 0 = one population), ``migration_interval``
            (10 generations), ``migrants`` (2 per neighbour), ``topology``
            (``"ring"``, ``"fully-connected"``, ``"random"``), ``topology_seed``,
            ``asynchronous`` (False: synchronous migration, repeatable).
            ``"nelder-mead"`` takes ``start``, ``initial_step`` (0.1),
            ``x_tolerance`` (1e-10), ``f_tolerance`` (1e-14),
            ``max_evaluations`` (20000), ``restarts`` (3) and ``wall_time``.
            ``reference``: the hypervolume's reference point for a Problem with
            several objectives (one value per objective).
            Unknown options raise :class:`~hulahoops.InvalidOptionError` naming them.
        callback: ``callback(generation, best, evaluations)`` after every generation (0 = the initial
            population): ``best`` is the smallest feasible objective (a float, NaN if none) or, for several
            objectives, an array of each objective's smallest feasible value; ``evaluations`` counts so
            far. ``"nelder-mead"``: a generation per simplex iteration (its vertices), then the final
            simplex; pagmo's: a generation per ``population`` evaluations (the initial population, then
            each generation's offspring), then the final population. Returning True stops the run with
            its best so far (termination ``"Cancelled"``, no exception; pagmo's: the best evaluation so far); an
            exception it raises ends the run and propagates. Not with islands (InvalidOptionError). The
            result is the same with or without it; ``best_per_generation`` holds the same generations.
        verbose: print one progress line per generation to ``sys.stderr``
            (``optimise: generation 12, evaluations 1300, best 0.0123``).

    The same seed gives the same result on every run and thread count.

    Raises:
        KeyboardInterrupt: on Ctrl-C, with ``.result`` the :class:`OptimiseResult` of the best so far.
    """
    progress = progress_function(callback, verbose, "optimise")
    if isinstance(problem, str):
        raw = _core.optimise_builtin(problem, dimension, objectives, precision, algorithm, options, progress)
    else:
        if not isinstance(problem, Problem):
            if not (hasattr(problem, "fitness") and hasattr(problem, "get_bounds")):
                from .errors import InvalidArgumentError
                raise InvalidArgumentError("InvalidArgument",
                                           f"problem must be a hulahoops.Problem, a pygmo UDP (fitness, get_bounds) "
                                           f"or a built-in name, not {type(problem).__name__}",
                                           {"field": "problem"})
            problem = from_pygmo(problem)
        raw = _core.optimise_callable(problem.objective, problem.lower, problem.upper, problem.objectives,
                                      problem.inequality, problem.equality, precision, problem.name, algorithm,
                                      options, progress)
    interrupt = raw.pop("interrupt", None)
    known = {k: raw.pop(k) for k in list(raw) if k in OptimiseResult.__dataclass_fields__}
    return raise_if_interrupted(interrupt, OptimiseResult(**known, extra=raw))


def builtin_problem(name: str, dimension: int = 0, objectives: int = 0) -> dict[str, Any]:
    """Bounds and sizes of a built-in test problem: name, lower, upper, objectives, inequality, equality."""
    return _core.builtin_problem(name, dimension, objectives)


def evaluate_builtin(name: str, points: Any, dimension: int = 0, objectives: int = 0) -> np.ndarray:
    """Values of a built-in test problem at points ``(n, d)``, shape ``(n, k)``, computed in C++."""
    return _core.evaluate_builtin(name, dimension, objectives, points)
