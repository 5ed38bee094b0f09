"""Incremental dynamic analysis of one wall and one record (docs/model.md §5; Eqs. 15–16)."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from frp_assess.dynamics.ida_search import STATUS_TOO_MANY_RUNS, next_multiplier, search
from frp_assess.dynamics.kernel.params import STATUS_OK, kernel_record
from frp_assess.dynamics.options import IDA_MAX_MULTIPLIER, IDA_STEP_RATIO, IDA_TOLERANCE
from frp_assess.dynamics.rocking import (
    COLLAPSE_FATES,
    FATE_NAMES,
    FailureMode,
    RockingModel,
    failure_mode_of,
)
from frp_assess.errors import Cancelled, NumericalError

#: Whether each kernel fate code is a collapse (indexed by the code), for the compiled search.
_COLLAPSE_FATE = np.array(
    [FATE_NAMES.get(code) in COLLAPSE_FATES for code in range(max(FATE_NAMES) + 1)]
)
#: Time histories the bisection may add to the hunt's: it halves C_hi − C_lo each time, and
#: 64 halvings of a step ratio exhaust a double's precision.
_BISECTION_ROOM = 64


@dataclass(frozen=True)
class IdaSettings:
    """Search rule of docs/model.md §5 (defaults and the ranges a user may ask for:
    :data:`~frp_assess.dynamics.options.IDA_OPTIONS`; the checks here are the wider ones of
    the search itself).

    Attributes:
        step_ratio: s, the hunt tries C₀·s^k, k = 0, 1, 2, …
        tolerance: bisection stops when (C_hi − C_lo) ≤ tolerance·C_hi.
        max_multiplier: give up (no collapse) beyond C_max = max_multiplier·C₀.
    """

    step_ratio: float = IDA_STEP_RATIO.default
    tolerance: float = IDA_TOLERANCE.default
    max_multiplier: float = IDA_MAX_MULTIPLIER.default

    def __post_init__(self) -> None:
        if not (math.isfinite(self.step_ratio) and self.step_ratio > 1.0):
            raise ValueError(f"IDA step ratio must be > 1, got {self.step_ratio!r}")
        if not (math.isfinite(self.tolerance) and 0.0 < self.tolerance <= 0.1):
            raise ValueError(f"IDA tolerance must be in (0, 0.1], got {self.tolerance!r}")
        if not (math.isfinite(self.max_multiplier) and self.max_multiplier > 1.0):
            raise ValueError(f"IDA max multiplier must be > 1, got {self.max_multiplier!r}")


@dataclass(frozen=True)
class IdaPoint:
    """One time history of an IDA."""

    multiplier: float  #: C [-]
    collapsed: bool
    peak_ratio: float  #: peak |θ|/α_x [-] (the fall itself included when it collapsed)


@dataclass(frozen=True)
class IdaResult:
    """Collapse of one wall under one record.

    ``collapse_multiplier``, ``a_dyn`` and ``q`` are ``None`` when the wall did not collapse up
    to C_max.
    """

    #: PGA of the unscaled record [m/s²]; for a wall above the ground floor the runner
    #: states it for the ground record (a_dyn = C·pga), while C₀ is of the floor motion
    pga: float
    c0: float  #: C₀ = a_RM / PGA of the motion at the base, below which nothing moves [-]
    collapse_multiplier: float | None  #: C of the first collapse [-]
    a_dyn: float | None  #: C·PGA [m/s²] (Eq. 16)
    q: float | None  #: a_dyn / a_RM [-] (Eq. 15)
    runs: int  #: time histories computed
    #: the largest C run without collapse (the bisection's C_lo, or the last step of the hunt
    #: when nothing collapsed); None when the first try, C₀, already collapsed [-]
    survivor_multiplier: float | None
    #: every time history the search ran, sorted by C: the IDA curve (a wall that stands
    #: again above its first collapse shows here)
    curve: tuple[IdaPoint, ...] = ()
    #: how the wall failed at the first collapse (docs/model.md §1.1): overturning, rupture
    #: then overturning, crushing, rupture then crushing; None without collapse
    failure_mode: FailureMode | None = None


def ida(
    model: RockingModel,
    acc: NDArray[np.float64],
    dt: float,
    settings: IdaSettings = IdaSettings(),
    *,
    should_stop: Callable[[], bool] | None = None,
    compiled: bool = True,
) -> IdaResult:
    """First collapse multiplier of ``model`` under the record ``acc`` [m/s²] sampled every dt [s].

    1. C₀ = a_RM/PGA; try C = C₀·s^k, k = 0, 1, … until the first collapse, giving up past
       C_max = max_multiplier·C₀;
    2. bisect between the last survivor and the first collapse until
       (C_hi − C_lo) ≤ tol·C_hi; the result is C_hi, the *first* collapse, and C_lo, the
       largest multiplier run without collapse (what "just below collapse" means).

    ``should_stop`` is polled before the search (its time histories run in one compiled
    call, :func:`~frp_assess.dynamics.ida_search.search`); when it returns True the search
    raises :class:`~frp_assess.errors.Cancelled`.  ``compiled=False`` drives the same search
    from Python instead, one ``model.run`` per time history from the record's first sample
    (the reference the compiled search is tested and benchmarked against; any model with
    ``a_rm``, ``crushing_rotation`` and ``run`` takes this path).

    A centred bar already inside the compressed zone of the weight (x_W ≥ B/2, θ_cr = 0)
    crushes the toe as the wall uplifts: the first collapse is C₀, no time history is run.
    """
    acc = kernel_record(acc)
    pga = float(np.max(np.abs(acc)))
    if not (math.isfinite(pga) and pga > 0.0):
        raise ValueError("the record has no ground motion (PGA = 0 or not finite)")
    if acc.ndim != 1 or acc.size < 2:
        raise ValueError("the record needs at least two samples")
    if not (math.isfinite(dt) and dt > 0.0):
        raise ValueError(f"dt must be > 0 s, got {dt!r}")
    a_rm = model.a_rm  # g·tan α_x (docs/model.md §1.1)
    c0 = a_rm / pga
    c_max = settings.max_multiplier * c0

    if model.crushing_rotation == 0.0:
        crushed = IdaPoint(c0, True, 0.0)
        return IdaResult(pga, c0, c0, c0 * pga, c0 * pga / a_rm, 0, None, (crushed,), "crushing")
    hunt: list[float] = []  # C₀·s^k up to C_max
    while (c := c0 * settings.step_ratio ** len(hunt)) <= c_max * (1.0 + 1e-12):
        hunt.append(c)
    if compiled and isinstance(model, RockingModel):
        if should_stop is not None and should_stop():
            raise Cancelled("IDA cancelled")
        points, modes = _compiled_search(model, acc, dt, np.array(hunt), settings.tolerance)
    else:
        points, modes = _search_in_python(model, acc, dt, np.array(hunt), settings, should_stop)
    n = len(points)
    standing = [p.multiplier for p in points if not p.collapsed]
    survivor = max(standing) if standing else None  # the hunt's and bisection's C_lo
    curve = tuple(sorted(points, key=lambda p: p.multiplier))
    if not modes:
        return IdaResult(pga, c0, None, None, None, n, survivor, curve, None)
    c_hi = min(modes)  # every collapse lowered C_hi: the last one is the least
    return IdaResult(pga, c0, c_hi, c_hi * pga, c_hi * pga / a_rm, n, survivor, curve, modes[c_hi])


def _compiled_search(
    model: RockingModel, acc: NDArray[np.float64], dt: float, hunt: NDArray[np.float64], tol: float
) -> tuple[list[IdaPoint], dict[float, FailureMode | None]]:
    """The time histories of the search in one compiled call (:func:`.ida_search.search`):
    the points, and the failure mode of each C that collapsed."""
    room = hunt.size + _BISECTION_ROOM
    multiplier = np.empty(room)
    fate = np.empty(room, dtype=np.int64)
    peak = np.empty(room)
    ruptures = np.empty(room, dtype=np.int64)
    n, status = search(
        acc, float(dt), model.tail_samples(dt), model.params, hunt, float(tol),
        multiplier, fate, peak, ruptures, _COLLAPSE_FATE,
    )  # fmt: skip
    if status != STATUS_OK:
        c_bad = float(multiplier[n - 1])
        if status != STATUS_TOO_MANY_RUNS:
            model.run(acc, dt, c_bad)  # the same time history: raises the kernel's message
        raise NumericalError(
            f"IDA at multiplier C = {c_bad:.6g}: the search did not end after {n} time "
            f"histories (bisection tolerance {tol:g})"
        )
    alpha = model.alpha
    points = []
    modes: dict[float, FailureMode | None] = {}
    for j in range(n):
        c = float(multiplier[j])
        collapsed = bool(_COLLAPSE_FATE[fate[j]])
        points.append(IdaPoint(c, collapsed, float(peak[j]) / alpha))
        if collapsed:
            modes[c] = failure_mode_of(FATE_NAMES[int(fate[j])], bool(ruptures[j]))
    return points, modes


def _search_in_python(
    model: RockingModel,
    acc: NDArray[np.float64],
    dt: float,
    hunt: NDArray[np.float64],
    settings: IdaSettings,
    should_stop: Callable[[], bool] | None,
) -> tuple[list[IdaPoint], dict[float, FailureMode | None]]:
    """The same search (:func:`.ida_search.next_multiplier`) with one ``model.run`` per time
    history, from the record's first sample: for any object with the
    :meth:`RockingModel.run` interface (the tests' stand-ins, the compiled search's
    reference)."""
    points: list[IdaPoint] = []
    modes: dict[float, FailureMode | None] = {}
    c_lo, c_hi = 0.0, math.nan
    while not math.isnan(
        c := float(next_multiplier(hunt, settings.tolerance, len(points), c_lo, c_hi))
    ):
        if should_stop is not None and should_stop():
            raise Cancelled("IDA cancelled")
        res = model.run(acc, dt, c)
        points.append(IdaPoint(c, res.collapsed, res.max_rotation_ratio))
        if res.collapsed:
            modes[c] = res.failure_mode
            c_hi = c
        else:
            c_lo = c
    return points, modes
