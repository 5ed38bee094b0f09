"""The jumps of the state at the events of Eq. 10 (docs/model.md §3.2–3.4): uplift from rest,
impact at θ = 0 (and when the bounces after it surely die out), rupture of a bar at θ_max.

The driver (:mod:`.simulate`) calls :func:`uplift_from_rest` while the wall rests and
:func:`jump` at every event it located inside a step; each returns the new (θ, θ') and
:class:`~.state.Regime`.  A new kind of event adds its branch to :func:`jump`.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from frp_assess.dynamics.kernel.inlining import into
from frp_assess.dynamics.kernel.params import (
    BAR_SHARED,
    REST_VELOCITY,
    RUPTURE_ENERGY_TRANSFER,
    TIE_ELASTIC,
    TIE_LOST,
    TIE_SLACK,
    TIE_YIELD,
    KernelParams,
    TieParams,
)
from frp_assess.dynamics.kernel.state import (
    Ground,
    Regime,
    acting_bar,
    rocking_on,
    tie_down_level,
    tie_up_level,
    with_bars,
    with_tie,
)
from frp_assess.dynamics.kernel.step_scan import (
    CRUSH,
    IMPACT,
    NO_EVENT,
    RUPTURE,
    TIE_DOWN,
    TIE_TURN,
)


@njit(cache=True, nogil=True, inline="always")
def uplift(
    ua: float, slope: float, x: float, x_end: float, prm: KernelParams
) -> tuple[float, float]:
    """From rest at x, the instant in [x, x_end) the wall uplifts, and its side (0: none).

    It starts with s = +1 when ü_g/g < −tan_+ and (two-sided only) with s = −1 when
    ü_g/g > tan_−; the input is linear, so the instant is exact.  Without loads both
    thresholds are tan α_x (docs/model.md §1.1); with them, a_RM,± of §12.
    """
    tan_p = prm.tan_pos
    tan_n = prm.tan_neg
    ux = ua + slope * x
    ue = ua + slope * x_end
    if ux < -tan_p:
        return x, 1.0
    if (not prm.one_sided) and ux > tan_n:
        return x, -1.0
    if ue < -tan_p:
        return x + (-tan_p - ux) / slope, 1.0
    if (not prm.one_sided) and ue > tan_n:
        return x + (tan_n - ux) / slope, -1.0
    return x_end, 0.0


@njit(cache=True, nogil=True, inline="always")
def impact(omega: float, s: float, prm: KernelParams) -> tuple[float, float, bool]:
    """Jump at θ = 0: (θ'₊, new s, at rest).  Two-sided: the pivot changes; one-sided: rebound."""
    if prm.one_sided:
        omega_new = -prm.e_to_pos * omega
        s_new = s
    else:
        s_new = -s
        omega_new = (prm.e_to_pos if s_new > 0.0 else prm.e_to_neg) * omega
    if abs(omega_new) < REST_VELOCITY * prm.p:
        return 0.0, s_new, True
    return omega_new, s_new, False


@njit(cache=True, nogil=True, inline="always")
def rupture(
    omega: float, s: float, intact_pos: bool, intact_neg: bool, prm: KernelParams
) -> tuple[float, bool, bool]:
    """Jump at θ_max: (θ'₊, bar for s = +1 intact, bar for s = −1 intact)."""
    if prm.bar_mode == BAR_SHARED:
        intact_pos = False
        intact_neg = False
    elif s > 0.0:
        intact_pos = False
    else:
        intact_neg = False
    if prm.rupture_mode == RUPTURE_ENERGY_TRANSFER:  # Eq. 12
        energy = prm.rupture_energy  # U_r/I0; with loads U_r/I_s = (U_r/I0)·p²_s/p²
        if prm.loaded:
            energy *= (prm.p2_pos if s > 0.0 else prm.p2_neg) / prm.p2
        omega = math.copysign(math.sqrt(omega * omega + 2.0 * energy), omega)
    return omega, intact_pos, intact_neg


#: The bounces after an impact are taken as dying out only when their whole sequence, bounded
#: from above, fits in this fraction of the time the input surely cannot uplift the wall.
CHATTER_SAFETY = 0.5
#: The longest stretch of record [samples] scanned for that time.
CHATTER_SAMPLES = 200


@njit(cache=True, nogil=True, inline=into("simulate"))
def ground_input(acc: np.ndarray, j: int, n_rec: int, inv_g: float) -> float:
    """u = ü_g/g at sample j of the record ``acc`` [m/s²] scaled by inv_g = C/g; 0 past the
    record (the tail of zero samples).  The driver's input (:mod:`.simulate`) and the bounces'
    bound read the record through it."""
    return acc[j] * inv_g if j < n_rec else 0.0


@njit(cache=True, nogil=True)
def restoring_at_rest(u: float, side: float, prm: KernelParams) -> float:
    """−side·θ'' of Eq. 10 at θ = 0 on ``side`` under u = ü_g/g [rad/s²]: what pulls a wall that
    leans to that side back to θ = 0 (≤ 0: the input tips it).  Linear in u:
    p²·(sin α − ξ + side·u·cos α)."""
    return prm.p2 * (prm.sin_a - prm.xi + side * u * prm.cos_a)


@njit(cache=True, nogil=True)
def chatter_ends(
    omega: float,
    s: float,
    acc: np.ndarray,
    i: int,
    x: float,
    dt: float,
    inv_g: float,
    n_rec: int,
    last: int,
    top: float,
    k_top: float,
    prm: KernelParams,
) -> bool:
    """After an impact at x [s] into the interval from sample i (θ = 0, θ' = ``omega``, leaning
    to s next): whether the bounces that follow surely die out before sample ``last``, so
    that the wall may be put at rest now (docs/model.md §3.3).

    Near θ = 0 a bounce is a flight under the restoring acceleration g of Eq. 10 at θ = 0
    (:func:`restoring_at_rest`), the next starting at e·v.  The input is linear between
    samples, so over a stretch of record g_min, the least g, is that of its samples (g ≤ 0
    anywhere means the input can uplift the wall: no).  The first and highest bounce,
    v²/(2·g_min), must stay below half of ``top`` (the peak so far and the level of every
    event: no new peak, no other event) and so low that θ's share of the acceleration,
    ∂θ''/∂θ·height (bounded with ``k_top``, the largest K of a side), is a tenth of g_min at
    most: the wall is pulled back by g_low = 0.9·g_min at least, and a flight lasts at most
    T = 2v/g_low.  That share depends on θ alone and gives the speed back on the way down;
    the change of the input does not: with δ(t) = g(t) − g(0), |δ'| ≤ ġ (ġ the largest rate
    of change of g), the flight returns with its speed changed by ∫₀ᵀ δ(t)·(2t/T − 1) dt,
    at most ġ·T²/4, so every bounce's speed shrinks at least by e' = e·(1 + ġ·v/g_low²) < 1
    and the whole sequence lasts less than 2v/(g_low·(1 − e')).  The stretch is extended
    sample by sample (to ``last`` and CHATTER_SAMPLES at most) until that bound fits in
    CHATTER_SAFETY of it.  The wall is then at rest before the stretch ends, whatever is
    integrated, and every later instant is the same: no input before its end can uplift it.
    """
    v = abs(omega)
    if not (v > 0.0 and prm.e_impact < 1.0):  # elastic impacts: the bounces never die out
        return False
    two_sided = not prm.one_sided
    u_a = ground_input(acc, i, n_rec, inv_g)
    u_b = ground_input(acc, i + 1, n_rec, inv_g)
    u_x = u_a + (u_b - u_a) * (x / dt)
    # the least restoring acceleration over the stretch, from its worst side and sample
    worst = min(-abs(u_x), -abs(u_b)) if two_sided else min(s * u_x, s * u_b)
    u_big = max(abs(u_x), abs(u_b))
    slope = abs(u_b - u_a) / dt
    rest = dt - x
    # the flights' bound with the first interval's g (it can only grow as the stretch does)
    g_first = restoring_at_rest(worst, 1.0, prm)  # worst: the least side·u
    if not g_first > 0.0:
        return False
    if 2.0 * v / (g_first * (1.0 - prm.e_impact)) > CHATTER_SAFETY * (rest + CHATTER_SAMPLES * dt):
        return False  # not within the longest stretch scanned, whatever the input does
    j = i + 1
    while True:
        g_min = restoring_at_rest(worst, 1.0, prm)
        if not g_min > 0.0:
            return False
        height = v * v / (2.0 * g_min)
        stiff = prm.p2 * (
            k_top + 1.0 + u_big * prm.sin_a + prm.xi * (2.0 + k_top * prm.kappa_per_k)
        )
        if not (2.0 * height < top and stiff * height <= 0.1 * g_min):
            return False
        g_low = 0.9 * g_min  # θ's share of the acceleration taken off
        g_dot = prm.p2 * prm.cos_a * slope
        e = prm.e_impact * (1.0 + g_dot * v / (g_low * g_low))
        if not e < 1.0:
            return False
        if 2.0 * v / (g_low * (1.0 - e)) <= CHATTER_SAFETY * rest:
            return True
        if j >= last or j - i >= CHATTER_SAMPLES:
            return False
        u_c = ground_input(acc, j + 1, n_rec, inv_g)
        worst = min(worst, -abs(u_c)) if two_sided else min(worst, s * u_c)
        u_big = max(u_big, abs(u_c))
        slope = max(slope, abs(u_c - u_b) / dt)
        u_b = u_c
        rest += dt
        j += 1


@njit(cache=True, nogil=True)
def uplift_from_rest(
    r: Regime, ua: float, slope: float, x: float, x_end: float, prm: KernelParams
) -> tuple[float, Regime, int]:
    """The wall at rest at x [s] into a sample interval whose input is ua + slope·τ [g]:
    (the instant it uplifts, or x_end; the regime then; the event there: CRUSH when the toe
    crushes as it uplifts, x_W already reaching the acting intact bar (θ_cr ≤ 0), else
    NO_EVENT).  See :func:`uplift`."""
    x, side = uplift(ua, slope, x, x_end, prm)
    if side == 0.0:
        return x, r, NO_EVENT
    r = rocking_on(r, side, False)
    return x, r, CRUSH if prm.theta_cr <= 0.0 and acting_bar(r) else NO_EVENT


@njit(cache=True, nogil=True)
def jump(
    event: int, level: float, omega: float, r: Regime, prm: KernelParams
) -> tuple[float, float, Regime]:
    """(θ, θ', regime) just after ``event`` (a step_scan code) located at s·θ = ``level`` with
    θ' = ``omega``: the impact's and the rupture's jumps; at the toe crushing and the collapse
    level the state is kept (the verdict ends the time history there).  The ties' events are
    :func:`tie_jump`'s, which the driver inlines (the tie's constants are not passed here)."""
    if event == IMPACT:
        omega, s, resting = impact(omega, r.s, prm)
        return 0.0, omega, rocking_on(r, s, resting)
    theta = r.s * level
    if event == RUPTURE:
        omega, intact_pos, intact_neg = rupture(omega, r.s, r.intact_pos, r.intact_neg, prm)
        return theta, omega, with_bars(r, intact_pos, intact_neg)
    return theta, omega, r


@njit(cache=True, nogil=True, inline="always")
def tie_jump(event: int, level: float, theta: float, r: Regime, ties: TieParams) -> Regime:
    """The ties' new states at their ``event`` (a step_scan code) at s·θ = ``level`` > 0
    (docs/model.md §12): every tie level whose own event is at that level changes; θ and θ'
    do not jump.

    Upward: a slack tie is re-engaged (elastic); an elastic one yields at F_y, or is lost when
    its force reaches F_a < F_y (it carries nothing afterwards: its elastic energy
    ½·k_t·(δ − δ_p)² leaves with it, θ' is kept).  Downward: it goes slack.  At the turning
    point every level that yields unloads, elastic, with δ_p = h_t·sin θ − F_y/k_t.
    """
    for j in range(ties.levels):
        state = r.tie[j]
        dp = r.tie_dp[j]
        if event == TIE_DOWN:
            if tie_down_level(r, j) == level:
                r = with_tie(r, j, TIE_SLACK, dp, ties)
        elif event == TIE_TURN:
            if state == TIE_YIELD:
                dp = max(dp, ties.height[j] * math.sin(theta) - ties.yield_elongation[j])
                r = with_tie(r, j, TIE_ELASTIC, dp, ties)
        elif tie_up_level(r, j, ties) == level:
            if state == TIE_SLACK:
                r = with_tie(r, j, TIE_ELASTIC, dp, ties)
            elif r.tie_yield[j] < ties.theta_loss[j]:
                r = with_tie(r, j, TIE_YIELD, dp, ties)
            else:
                r = with_tie(r, j, TIE_LOST, dp, ties)
    return r


@njit(cache=True, nogil=True, inline="always")
def bounces_die_out(
    omega: float,
    r: Regime,
    free: bool,
    ground: Ground,
    i: int,
    x: float,
    last: int,
    peak: float,
    bar_level: float,
    limit: float,
    prm: KernelParams,
) -> bool:
    """Right after an impact at x [s] into the interval from sample i (θ' = ``omega``, regime
    r): whether the wall is put at rest now, because the bounces surely die out where the
    input cannot uplift it, before sample ``last`` (:func:`chatter_ends`; never during the
    free vibration, nor when ``prm.settle_chatter`` is off).  ``peak``, ``bar_level`` and
    ``limit`` bound the height a bounce may reach: below the peak so far and every event
    level."""
    if not prm.settle_chatter or r.resting or free:
        return False
    any_bar = r.intact_pos or r.intact_neg
    return chatter_ends(
        omega,
        r.s,
        ground.acc,
        i,
        x,
        ground.dt,
        ground.scale / prm.g,
        ground.acc.shape[0],
        last,
        min(peak, bar_level) if any_bar else min(peak, limit),
        prm.k_bar if any_bar else 0.0,
        prm,
    )
