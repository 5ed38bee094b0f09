"""Incremental dynamic analysis of one wall and one record (docs/model.md §5; Eqs. 15–16)."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from frp_assess.dynamics.options import IDA_MAX_MULTIPLIER, IDA_STEP_RATIO, IDA_TOLERANCE
from frp_assess.dynamics.rocking import FailureMode, RockingModel
from frp_assess.errors import Cancelled


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
) -> IdaResult:
    """First collapse multiplier of ``model`` under the record ``acc`` [m/s²] sampled every dt [s].

    1. C₀ = a_RM/PGA; try C = C₀·s^k, k = 0, 1, … until the first collapse, giving up past
       C_max = max_multiplier·C₀;
    2. bisect between the last survivor and the first collapse until
       (C_hi − C_lo) ≤ tol·C_hi; the result is C_hi, the *first* collapse, and C_lo, the
       largest multiplier run without collapse (what "just below collapse" means).

    ``should_stop`` is polled between time histories; when it returns True the search
    raises :class:`~frp_assess.errors.Cancelled`.

    A centred bar already inside the compressed zone of the weight (x_W ≥ B/2, θ_cr = 0)
    crushes the toe as the wall uplifts: the first collapse is C₀, no time history is run.
    """
    acc = np.ascontiguousarray(acc, dtype=np.float64)
    pga = float(np.max(np.abs(acc)))
    if not (math.isfinite(pga) and pga > 0.0):
        raise ValueError("the record has no ground motion (PGA = 0 or not finite)")
    a_rm = model.a_rm  # g·tan α_x (docs/model.md §1.1)
    c0 = a_rm / pga
    c_max = settings.max_multiplier * c0
    points: list[IdaPoint] = []
    modes: dict[float, FailureMode | None] = {}

    if model.crushing_rotation == 0.0:
        crushed = IdaPoint(c0, True, 0.0)
        return IdaResult(pga, c0, c0, c0 * pga, c0 * pga / a_rm, 0, None, (crushed,), "crushing")

    def collapses(c: float) -> bool:
        if should_stop is not None and should_stop():
            raise Cancelled("IDA cancelled")
        res = model.run(acc, dt, c)
        points.append(IdaPoint(c, res.collapsed, res.max_rotation_ratio))
        modes[c] = res.failure_mode
        return res.collapsed

    def result(c_hi: float | None, c_lo: float) -> IdaResult:
        curve = tuple(sorted(points, key=lambda p: p.multiplier))
        a_dyn = None if c_hi is None else c_hi * pga
        q = None if a_dyn is None else a_dyn / a_rm
        mode = None if c_hi is None else modes[c_hi]
        return IdaResult(pga, c0, c_hi, a_dyn, q, len(points), c_lo or None, curve, mode)

    c_lo = 0.0
    c_hi = math.nan
    k = 0
    while True:
        c = c0 * settings.step_ratio**k
        if c > c_max * (1.0 + 1e-12):
            return result(None, c_lo)
        if collapses(c):
            c_hi = c
            break
        c_lo = c
        k += 1
    while c_hi - c_lo > settings.tolerance * c_hi:
        c_mid = 0.5 * (c_lo + c_hi)
        if collapses(c_mid):
            c_hi = c_mid
        else:
            c_lo = c_mid
    return result(c_hi, c_lo)
