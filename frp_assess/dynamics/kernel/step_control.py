"""Step-size control of the time-stepping driver (docs/model.md §4): how long the next step
is, whether a step is accepted, and whether an accepted step is quiet (no event, no new peak).

Called by :mod:`.simulate`; numbers only.
"""

from __future__ import annotations

import math

from numba import njit

from frp_assess.dynamics.kernel.params import STEP_GROWTH_MAX, STEP_SAFETY, STEP_SHRINK_MIN

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
