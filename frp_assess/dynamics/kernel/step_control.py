"""The integrator of the time-stepping driver (docs/model.md §4.2): one step and its error
control (:func:`try_step`), how long the next step is, whether a step is accepted, and whether an
accepted step is quiet (no event, no new peak).

Called by :mod:`.simulate`; numbers only.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from numba import njit

from frp_assess.dynamics.kernel.params import (
    METHOD_DOPRI5,
    METHOD_RK4,
    MIN_STEP_FRACTION,
    STEP_GROWTH_MAX,
    STEP_SAFETY,
    STEP_SHRINK_MIN,
    KernelParams,
)
from frp_assess.dynamics.kernel.steppers import acceleration, step

#: A step that would leave less than this fraction of itself before the next sample is
#: stretched to the sample; shorter steps divide the rest of the interval equally.
SLIVER = 0.01


@njit(cache=True, nogil=True)
def step_length(h: float, rest: float, equal: bool) -> float:
    """The step to take when ``rest`` [s] remain to the next sample and h is proposed: the
    rest itself when h nearly reaches it, else h, or (``equal``) the rest divided into equal
    steps no longer than h, so that no sliver is left before the sample."""
    if h >= rest * (1.0 - SLIVER):
        return rest
    if equal:
        return rest / math.ceil(rest / h)
    return h


@njit(cache=True, nogil=True)
def step_size(
    err: float,
    hh: float,
    h: float,
    exponent: float,
    err_grow_max: float,
    h_enough: float,
    order: int,
) -> tuple[bool, float]:
    """Error control: (accept the step of length hh, the next step length [s]).

    A step is accepted when err ≤ 1 (NaN never); the next one is hh·0.9·err^exponent within
    [0.2, 5]·hh, exponent = −1/order.  Below ``err_grow_max`` (:func:`grow_threshold`) the
    factor is 5 and the power is not evaluated: the steps that the record's samples cut short
    are the common case, and ``pow`` was a tenth of the kernel's time.

    ``h_enough`` [s]: a proposal at least this long is as good as any longer one (every step
    ends at the next record sample, at most dt away, and :func:`step_length` takes all the
    rest of the interval whenever h ≥ (1 − SLIVER)·rest).  When 0.9·err^exponent·hh surely
    reaches it (err ≤ (0.9·hh/h_enough)^order, an integer power), 5·hh is returned without
    the power: a different number, the same next step.  With one step per record sample this
    spares the power on most of the steps above ``err_grow_max`` (63 % of all steps on the
    paper's grid).
    """
    if not err <= 1.0:
        shrink = STEP_SHRINK_MIN
        if err < 1e300:
            shrink = max(STEP_SHRINK_MIN, STEP_SAFETY * err**exponent)
        return False, hh * shrink
    grow = STEP_GROWTH_MAX
    if err > err_grow_max:
        enough = STEP_SAFETY * hh / h_enough
        if err <= (1.0 - 1e-9) * enough**order:
            return True, hh * STEP_GROWTH_MAX
        grow = min(STEP_GROWTH_MAX, max(STEP_SHRINK_MIN, STEP_SAFETY * err**exponent))
    return True, hh * grow


@njit(cache=True, nogil=True)
def grow_threshold(exponent: float) -> float:
    """The error below which 0.9·err^exponent exceeds the largest growth 5 (kept a part in
    10⁹ below the exact bound, so the factor is the same as with the power evaluated)."""
    bound: float = (STEP_GROWTH_MAX / STEP_SAFETY) ** (1.0 / exponent)
    return (1.0 - 1e-9) * bound


@njit(cache=True, nogil=True)
def quiet(y0: float, y1: float, m0: float, m1: float, top: float) -> bool:
    """Whether the Hermite cubic through (0, y0), (1, y1) with slopes m0, m1 stays inside
    (0, top) for u in (0, 1]: its Bernstein control points y0, y0 + m0/3, y1 − m1/3, y1 do (the
    cubic lies in their convex hull).  Then the step holds no event and no turning point above
    ``top``, and the critical points and crossings need not be computed (most steps).

    y0 = 0 is allowed when the other three are positive: the step that starts at an impact
    (about a tenth of all steps) leaves θ = 0 at once and stays away from it, and its search
    would find nothing (a crossing needs the cubic above 0 at the start of its piece).
    """
    b1 = y0 + m0 / 3.0
    b2 = y1 - m1 / 3.0
    return y0 >= 0.0 and min(min(y1, b1), b2) > 0.0 and max(max(y0, y1), max(b1, b2)) < top


class Stepping(NamedTuple):
    """The constants of the step control of one time history (:func:`stepping`)."""

    adaptive: bool  #: an embedded pair with error control (else RK4 at ``h_fixed``)
    order: int  #: q + 1, q the order of the embedded error estimate
    exponent: float  #: −1/order, the step-size exponent
    err_grow_max: float  #: :func:`grow_threshold` of the exponent
    h_enough: float  #: a proposal this long reaches the next sample [s] (:func:`step_size`)
    h_fixed: float  #: RK4's step: dt divided into equal steps no longer than fixed_step [s]
    h_start: float  #: the first proposal of every rocking phase [s]
    h_min: float  #: below this step the error control gives up [s]


@njit(cache=True, nogil=True, inline="always")
def stepping(dt: float, prm: KernelParams) -> Stepping:
    """The step control's constants for records sampled every dt [s].

    The first proposal of a rocking phase, min(dt, 0.05/p), is made at the start and again at
    every uplift from rest, so that a phase does not depend on how the one before it came to
    rest.
    """
    adaptive = prm.method != METHOD_RK4
    order = 5 if prm.method == METHOD_DOPRI5 else 3
    exponent = -1.0 / order
    h_fixed = dt / max(1, int(math.ceil(dt / prm.fixed_step - 1e-9))) if not adaptive else dt
    return Stepping(
        adaptive,
        order,
        exponent,
        grow_threshold(exponent),
        (1.0 - SLIVER) * dt,  # every step ends at a sample, at most dt away
        h_fixed,
        h_fixed if not adaptive else min(dt, 0.05 / prm.p),
        MIN_STEP_FRACTION * dt,
    )


@njit(cache=True, nogil=True, inline="always")
def try_step(
    theta: float,
    omega: float,
    a1: float,
    need_a: bool,
    h: float,
    u0: float,
    slope: float,
    rest: float,
    s: float,
    k_s: float,
    t0: float,
    t1: float,
    ctl: Stepping,
    prm: KernelParams,
) -> tuple[float, float, float, float, float, float, bool]:
    """One step of the integrator and its error control, from (θ, θ') with θ'' = a1 (computed
    here when ``need_a``), the proposal h [s] and ``rest`` [s] left to the next sample, under
    the ground u0 + slope·τ [g] in the regime (s, K_s), frozen for the step.

    Returns (θ, θ', θ'' at the end, a1, the step taken hh [s], the next proposal [s],
    accepted): the driver retries a rejected step with the shorter proposal
    (:func:`step_size`) until one is accepted or the proposal falls below ``ctl.h_min``.
    The retry loop is the driver's: inside this function it made the IDAs 2.5 % slower
    (benchmarks/bench_kernel_against.py, 2026-11-28).  numba inlines it into the driver
    (:mod:`.inlining`).
    """
    if need_a:
        a1 = acceleration(theta, s, u0, k_s, t0, t1, prm)
    hh = step_length(h if ctl.adaptive else ctl.h_fixed, rest, ctl.adaptive)
    th1, om1, a_end, err = step(theta, omega, hh, u0, slope, s, k_s, t0, t1, a1, prm)
    accepted = True
    if ctl.adaptive:
        accepted, h = step_size(err, hh, h, ctl.exponent, ctl.err_grow_max, ctl.h_enough, ctl.order)
    return th1, om1, a_end, a1, hh, h, accepted
