"""Incremental dynamic analysis of one wall and one record (docs/model.md §5; Eqs. 15–16)."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from frp_assess.dynamics.effective import (
    CELL_SUBDIVISIONS,
    COARSE_STEPS,
    EARLY_STOP_BAND,
    FIRST_COLLAPSE_MARGIN,
    effective_capacity,
    ladder,
)
from frp_assess.dynamics.ida_refine import new_refined_state, next_refined, refine_steps
from frp_assess.dynamics.ida_search import (
    LOST_BARS,
    LOST_TIE,
    STATUS_TOO_MANY_RUNS,
    new_state,
    next_multiplier,
    next_sample,
    sample,
    search,
)
from frp_assess.dynamics.kernel.params import STATUS_OK, kernel_record
from frp_assess.dynamics.options import (
    IDA_CAPACITY,
    IDA_LADDER_RATIO,
    IDA_MAX_MULTIPLIER,
    IDA_OFFSET,
    IDA_STEP_RATIO,
    IDA_TOLERANCE,
    CapacityRule,
)
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
    """Search rule of docs/model.md §5 and §11 (defaults and the ranges a user may ask for:
    :data:`~frp_assess.dynamics.options.IDA_OPTIONS`; the checks here are the wider ones of
    the search itself).

    Attributes:
        step_ratio: s, the hunt of §5 tries C₀·s^k, k = 0, 1, 2, …
        tolerance: bisection stops when (C_hi − C_lo) ≤ tolerance·C_hi.
        max_multiplier: give up (no collapse) beyond C_max = max_multiplier·C₀.
        capacity: ``effective`` (the effective collapse intensity of §11) or
            ``first-collapse`` (the first collapse of §5, the paper's convention).
        ladder_ratio: r, the ladder of §11 is C₀·r^(k+offset) (``first-collapse``
            ignores it).
        offset: a fraction of a step in [0, 1) (``first-collapse`` ignores it).
    """

    step_ratio: float = IDA_STEP_RATIO.default
    tolerance: float = IDA_TOLERANCE.default
    max_multiplier: float = IDA_MAX_MULTIPLIER.default
    capacity: CapacityRule = IDA_CAPACITY.default
    ladder_ratio: float = IDA_LADDER_RATIO.default
    offset: float = IDA_OFFSET.default

    def __post_init__(self) -> None:
        if not (math.isfinite(self.step_ratio) and self.step_ratio > 1.0):
            raise ValueError(f"IDA step ratio must be > 1, got {self.step_ratio!r}")
        if not (math.isfinite(self.tolerance) and 0.0 < self.tolerance <= 0.1):
            raise ValueError(f"IDA tolerance must be in (0, 0.1], got {self.tolerance!r}")
        if not (math.isfinite(self.max_multiplier) and self.max_multiplier > 1.0):
            raise ValueError(f"IDA max multiplier must be > 1, got {self.max_multiplier!r}")
        IDA_CAPACITY.check(self.capacity)
        if not (math.isfinite(self.ladder_ratio) and self.ladder_ratio > 1.0):
            raise ValueError(f"IDA ladder ratio must be > 1, got {self.ladder_ratio!r}")
        if not (math.isfinite(self.offset) and 0.0 <= self.offset < 1.0):
            raise ValueError(f"IDA offset must be in [0, 1), got {self.offset!r}")


@dataclass(frozen=True)
class IdaPoint:
    """One time history of an IDA."""

    multiplier: float  #: C [-]
    collapsed: bool
    peak_ratio: float  #: peak |θ|/α_x [-] (the fall itself included when it collapsed)


@dataclass(frozen=True)
class IdaResult:
    """Collapse of one wall under one record.

    ``collapse_multiplier``, ``a_dyn`` and ``q`` are the capacity of the rule ``capacity``
    (docs/model.md §5 / §11); ``None`` when the wall did not collapse up to C_max (with
    ``effective``: when it stood at the last sample), and ``bound_multiplier`` then holds the
    lower bound (C_max, or the effective intensity counted up to C_max).
    """

    #: PGA of the unscaled record [m/s²]; for a wall above the ground floor the runner
    #: states it for the ground record (a_dyn = C·pga), while C₀ is of the floor motion
    pga: float
    c0: float  #: C₀ = a_RM / PGA of the motion at the base, below which nothing moves [-]
    collapse_multiplier: float | None  #: C of the capacity (rule ``capacity``) [-]
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
    #: then overturning, crushing, rupture then crushing, tie lost then overturning, rupture
    #: and tie lost then overturning; None without collapse
    failure_mode: FailureMode | None = None
    #: the rule of ``collapse_multiplier``: effective | first-collapse
    capacity: CapacityRule = "first-collapse"
    #: the lowest C that collapsed on the sampling (the paper's convention); None: none [-]
    first_collapse: float | None = None
    #: collapse windows (runs of collapsed samples) that begin below the capacity [-]
    windows_below: int = 0
    #: without a capacity (``collapse_multiplier`` None): its lower bound [-]
    bound_multiplier: float | None = None

    @property
    def capacity_multiplier(self) -> float:
        """The capacity, or its lower bound without one [-]."""
        c = (
            self.collapse_multiplier
            if self.collapse_multiplier is not None
            else self.bound_multiplier
        )
        if c is None:
            raise ValueError("IDA result without a capacity or its bound")
        return c


def ida(
    model: RockingModel,
    acc: NDArray[np.float64],
    dt: float,
    settings: IdaSettings = IdaSettings(),
    *,
    should_stop: Callable[[], bool] | None = None,
    compiled: bool = True,
    band: float = EARLY_STOP_BAND,
    subdivide: int = CELL_SUBDIVISIONS,
    coarse: int = COARSE_STEPS,
) -> IdaResult:
    """The collapse capacity of ``model`` under the record ``acc`` [m/s²] sampled every dt [s],
    by the rule ``settings.capacity``.

    ``first-collapse`` (docs/model.md §5, the paper's convention):

    1. C₀ = a_RM/PGA; try C = C₀·s^k, k = 0, 1, … until the first collapse, giving up past
       C_max = max_multiplier·C₀;
    2. bisect between the last survivor and the first collapse until
       (C_hi − C_lo) ≤ tol·C_hi; the result is C_hi, the *first* collapse, and C_lo, the
       largest multiplier run without collapse (what "just below collapse" means).

    ``effective`` (§11): the effective collapse intensity
    (:func:`~frp_assess.dynamics.effective.effective_capacity`) of the samples that
    :func:`~frp_assess.dynamics.ida_refine.next_refined` chooses (§11.2, design (e)): the
    coarse ladder C₀·r^(8k+offset) up to its first collapse, the fine ladder C₀·r^(k+offset)
    from 1.35 below that up to C_max or until the wall has fallen at every point run over a
    band ``band`` (1.5), isolated changes of outcome bisected to the tolerance.  ``coarse``
    = 1: the plain ladder of :func:`~frp_assess.dynamics.ida_search.next_sample` instead,
    every cell whose ends disagree walked at ``subdivide`` times the density and every change
    of outcome bisected (``band``, ``subdivide``, ``coarse``: knobs for the measurements of
    benchmarks/effective_sampling*.py).

    ``should_stop`` is polled before the search (its time histories run in one compiled
    call, :func:`~frp_assess.dynamics.ida_search.search` / ``sample``); when it returns True
    the search raises :class:`~frp_assess.errors.Cancelled`.  ``compiled=False`` drives the
    same search from Python instead, one ``model.run`` per time history from the record's
    first sample (the reference the compiled search is tested and benchmarked against; any
    model with ``a_rm``, ``crushing_rotation`` and ``run`` takes this path).

    A centred bar already inside the compressed zone of the weight (x_W ≥ B/2, θ_cr = 0)
    crushes the toe as the wall uplifts: the capacity is C₀, no time history is run.
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
    rule = settings.capacity

    if model.crushing_rotation == 0.0:
        crushed = IdaPoint(c0, True, 0.0)
        return IdaResult(
            pga, c0, c0, c0 * pga, c0 * pga / a_rm, 0, None, (crushed,), "crushing", rule, c0
        )
    if rule == "first-collapse":
        hunt: list[float] = []  # C₀·s^k up to C_max
        while (c := c0 * settings.step_ratio ** len(hunt)) <= c_max * (1.0 + 1e-12):
            hunt.append(c)
        steps = np.array(hunt)
    else:
        steps = ladder(c0, c_max, settings.ladder_ratio, settings.offset)
    n_below, band_steps = refine_steps(settings.ladder_ratio, FIRST_COLLAPSE_MARGIN, band)
    plan = _Plan(
        rule, steps, c0, settings.tolerance, band, subdivide, coarse, n_below, band_steps,
        settings.offset > 0.0,
    )  # fmt: skip
    if compiled and isinstance(model, RockingModel):
        if should_stop is not None and should_stop():
            raise Cancelled("IDA cancelled")
        points, modes = _compiled_search(model, acc, dt, plan)
    else:
        points, modes = _search_in_python(model, acc, dt, plan, should_stop)
    n = len(points)
    curve = tuple(sorted(points, key=lambda p: p.multiplier))
    first = min(modes) if modes else None
    if rule == "first-collapse":
        standing = [p.multiplier for p in points if not p.collapsed]
        survivor = max(standing) if standing else None  # the hunt's and bisection's C_lo
        if first is None:
            return IdaResult(
                pga, c0, None, None, None, n, survivor, curve, None, rule, None, 0, c_max
            )
        # every collapse lowered C_hi: the last one is the least
        return IdaResult(
            pga, c0, first, first * pga, first * pga / a_rm, n, survivor, curve, modes[first],
            rule, first,
        )  # fmt: skip
    eff = effective_capacity([(p.multiplier, p.collapsed) for p in points], c0, c_max)
    a_c = eff.multiplier
    below = [p.multiplier for p in curve if not p.collapsed and p.multiplier <= a_c]
    survivor = max(below) if below else None
    # the failure mode of the first collapse at or above a_c (where the wall "falls")
    above = [c for c in modes if c >= a_c]
    mode = modes[min(above)] if above else (modes[max(modes)] if modes else None)
    if eff.lower_bound:
        return IdaResult(
            pga, c0, None, None, None, n, survivor, curve, mode, rule, first, eff.windows_below,
            a_c,
        )  # fmt: skip
    return IdaResult(
        pga, c0, a_c, a_c * pga, a_c * pga / a_rm, n, survivor, curve, mode, rule, first,
        eff.windows_below,
    )  # fmt: skip


@dataclass(frozen=True)
class _Plan:
    """What the search runs: the rule, its ladder (the hunt of §5 or the ladder of §11), C₀,
    the bisection tolerance and the early-stop band of §11."""

    rule: CapacityRule
    steps: NDArray[np.float64]
    c0: float
    tolerance: float
    band: float
    subdivide: int
    coarse: int  #: > 1: the default sampling of ida_refine; 1: the plain ladder
    below: int  #: fine steps of the first collapse's walk below it
    band_steps: int  #: the early-stop band in fine steps (-1: never)
    shifted: bool  #: offset > 0


def _compiled_search(
    model: RockingModel, acc: NDArray[np.float64], dt: float, plan: _Plan
) -> tuple[list[IdaPoint], dict[float, FailureMode | None]]:
    """The time histories of the search in one compiled call (:func:`.ida_search.search` or
    :func:`.ida_search.sample`): the points, and the failure mode of each C that collapsed."""
    # the effective rule bisects every transition of its ladder: room for each one
    cells = 1 if plan.rule == "first-collapse" else plan.subdivide * (plan.steps.size + 1)
    room = plan.steps.size + _BISECTION_ROOM * cells
    multiplier = np.empty(room)
    fate = np.empty(room, dtype=np.int64)
    peak = np.empty(room)
    losses = np.empty(room, dtype=np.int64)
    tol = float(plan.tolerance)
    if plan.rule == "first-collapse":
        n, status = search(
            acc, float(dt), model.tail_samples(dt), model.params, model.tie_params, plan.steps, tol,
            multiplier, fate, peak, losses, _COLLAPSE_FATE,
        )  # fmt: skip
    else:
        n, status = sample(
            acc, float(dt), model.tail_samples(dt), model.params, model.tie_params, plan.steps,
            float(plan.c0),
            tol, float(plan.band), int(plan.subdivide), int(plan.coarse), int(plan.below),
            int(plan.band_steps), bool(plan.shifted), multiplier, fate, peak, losses,
            _COLLAPSE_FATE,
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
            lost = int(losses[j])
            modes[c] = failure_mode_of(
                FATE_NAMES[int(fate[j])], bool(lost & LOST_BARS), bool(lost & LOST_TIE)
            )
    return points, modes


def _search_in_python(
    model: RockingModel,
    acc: NDArray[np.float64],
    dt: float,
    plan: _Plan,
    should_stop: Callable[[], bool] | None,
) -> tuple[list[IdaPoint], dict[float, FailureMode | None]]:
    """The same search (:func:`.ida_search.next_multiplier` / ``next_sample``) with one
    ``model.run`` per time history, from the record's first sample: for any object with the
    :meth:`RockingModel.run` interface (the tests' stand-ins, the compiled search's
    reference)."""
    points: list[IdaPoint] = []
    modes: dict[float, FailureMode | None] = {}
    c_lo, c_hi = 0.0, math.nan
    refined = plan.rule == "effective" and plan.coarse > 1
    state = new_refined_state(plan.steps.size, plan.coarse) if refined else new_state()
    collapsed = False

    def following() -> float:
        if plan.rule == "first-collapse":
            return float(next_multiplier(plan.steps, plan.tolerance, len(points), c_lo, c_hi))
        if refined:
            return float(
                next_refined(
                    plan.steps,
                    plan.tolerance,
                    plan.coarse,
                    plan.below,
                    plan.band_steps,
                    plan.shifted,
                    state,
                    collapsed,
                )  # fmt: skip
            )
        return float(
            next_sample(
                plan.steps, plan.c0, plan.tolerance, plan.band, plan.subdivide, state, collapsed
            )
        )

    while not math.isnan(c := following()):
        if should_stop is not None and should_stop():
            raise Cancelled("IDA cancelled")
        res = model.run(acc, dt, c)
        points.append(IdaPoint(c, res.collapsed, res.max_rotation_ratio))
        collapsed = bool(res.collapsed)
        if res.collapsed:
            modes[c] = res.failure_mode
            c_hi = c
        else:
            c_lo = c
    return points, modes
