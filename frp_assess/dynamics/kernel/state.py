"""The driver's state between two events, and where it writes (docs/model.md §3–4).

The wall's motion is (θ, θ') and changes with every step; everything else that decides how
it moves is its :class:`Regime`: the side it rocks on, whether it is at rest, which bars are
intact.  The regime is frozen inside a step (the steppers take its K_s) and changes only at
the events, by the jumps of :mod:`.jumps`.  Every new regime is built here, by the functions
below, so that a variable added to the regime (a tie's plastic elongation, a tie lost:
docs/model.md §12) is added in this file and in the jumps that change it, nowhere else.

:class:`Buffers` holds the arrays the caller hands the driver for what it returns beyond
its :class:`~.simulate.Outcome` (the history, the first ruptures); :class:`Ground` the input.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from frp_assess.dynamics.kernel.params import (
    BAR_NONE,
    TIE_ELASTIC,
    TIE_LOST,
    TIE_OFF,
    TIE_SLACK,
    TIE_YIELD,
    KernelParams,
    TieParams,
)


class Ground(NamedTuple):
    """The input of one time history: scale·acc [m/s²] every dt [s], then n_tail zero samples."""

    acc: np.ndarray  #: the record [m/s²], read-only (:func:`.params.kernel_record`)
    dt: float  #: sample interval [s]
    scale: float  #: the IDA's multiplier C [-]
    n_tail: int  #: zero samples after the record


class Buffers(NamedTuple):
    """Arrays the caller allocates and the driver fills (units: s, rad, rad/s)."""

    theta: np.ndarray  #: θ at every sample (length :func:`.simulate.history_length`, if kept)
    omega: np.ndarray  #: θ' at every sample
    bar: np.ndarray  #: 1.0 where an intact bar is stretched at the sample, else 0.0
    rupture_time: np.ndarray  #: the instants of the first ruptures (length ≥ 2)
    rupture_side: np.ndarray  #: their sides, ±1 (int64)


class Regime(NamedTuple):
    """What decides the wall's equation of motion besides (θ, θ'); constant inside a step."""

    s: float  #: the side it rocks on, ±1 (sgn θ; the pivot corner)
    resting: bool  #: at rest on its base (θ = θ' = 0): nothing is integrated
    intact_pos: bool  #: the bar acting for s = +1 is intact
    intact_neg: bool  #: the bar acting for s = −1 is intact
    # each tie level's (MAX_TIE_LEVELS entries; TIE_OFF beyond the wall's levels):
    tie: tuple[int, int]  #: its state, a TIE_* code of :mod:`.params`
    tie_dp: tuple[float, float]  #: its plastic elongation δ_p [m]
    tie_slack: tuple[float, float]  #: θ where it goes slack, asin(δ_p/h_t) [rad]
    #: θ where it yields, asin((δ_p + F_y/k_t)/h_t) [rad] (inf: never)
    tie_yield: tuple[float, float]


@njit(cache=True, nogil=True, inline="always")
def initial_regime(theta0: float, omega0: float, prm: KernelParams, ties: TieParams) -> Regime:
    """The regime of the initial state: at rest when it is (0, 0), the side θ0 (or θ'0) points
    to, every bar intact, the ties (if any) unstretched and elastic from θ = 0 (θ0 > 0
    stretches them at once: the initial state is the wall's, the ties taken as fitted at
    θ = 0)."""
    resting = theta0 == 0.0 and omega0 == 0.0
    s = -1.0 if (theta0 < 0.0 or (theta0 == 0.0 and omega0 < 0.0)) else 1.0
    bars = prm.bar_mode != BAR_NONE
    off = (TIE_OFF, TIE_OFF)
    zero = (0.0, 0.0)
    r = Regime(s, resting, bars, bars, off, zero, zero, (math.inf, math.inf))
    for j in range(ties.levels):
        r = with_tie(r, j, TIE_ELASTIC, 0.0, ties)
    return r


@njit(cache=True, nogil=True, inline="always")
def put(values: tuple, j: int, value: float | int) -> tuple:  # type: ignore[type-arg]
    """The tuple of a tie level's values with entry j replaced (MAX_TIE_LEVELS = 2 entries)."""
    return (
        value if j == 0 else values[0],
        value if j == 1 else values[1],
    )


@njit(cache=True, nogil=True, inline="always")
def tie_angle(elongation: float, height: float) -> float:
    """θ ∈ [0, π/2) at which a tie's elongation h_t·sin θ is ``elongation`` [m] (inf: never)."""
    ratio = elongation / height
    return math.asin(ratio) if ratio < 1.0 else math.inf


@njit(cache=True, nogil=True, inline="always")
def with_tie(r: Regime, j: int, state: int, dp: float, ties: TieParams) -> Regime:
    """The regime with tie level j's state and plastic elongation δ_p [m] changed (its levels
    with them)."""
    h = ties.height[j]
    slack = tie_angle(dp, h) if dp > 0.0 else 0.0
    yields = tie_angle(dp + ties.yield_elongation[j], h)
    return Regime(
        r.s, r.resting, r.intact_pos, r.intact_neg, put(r.tie, j, state), put(r.tie_dp, j, dp),
        put(r.tie_slack, j, slack), put(r.tie_yield, j, yields),
    )  # fmt: skip


@njit(cache=True, nogil=True, inline="always")
def tie_terms(r: Regime, ties: TieParams) -> tuple[float, float]:
    """(t0, t1): the ties' moment over W·R is cos θ·(t0 + t1·sin θ) in this regime (0 on side
    −): the sum over the levels, elastic k_t·h_t·(h_t·sin θ − δ_p)/(W·R), yielding
    F_y·h_t/(W·R), slack or lost nothing."""
    t0 = 0.0
    t1 = 0.0
    if r.s < 0.0:
        return t0, t1
    for j in range(ties.levels):
        state = r.tie[j]
        if state == TIE_YIELD:
            t0 += ties.kn[j] * ties.yield_elongation[j]
        elif state == TIE_ELASTIC:
            t0 -= ties.kn[j] * r.tie_dp[j]
            t1 += ties.kn[j] * ties.height[j]
    return t0, t1


@njit(cache=True, nogil=True, inline="always")
def tie_up_level(r: Regime, j: int, ties: TieParams) -> float:
    """Tie level j's next upward event as a level of θ on side + — re-engaged (slack), yields
    or is lost (elastic) — or inf."""
    state = r.tie[j]
    if state == TIE_SLACK:
        return r.tie_slack[j]
    if state == TIE_ELASTIC:
        return min(r.tie_yield[j], ties.theta_loss[j])
    return math.inf


@njit(cache=True, nogil=True, inline="always")
def tie_down_level(r: Regime, j: int) -> float:
    """Tie level j's downward event (it goes slack: elastic with δ_p > 0) as a level of θ, or 0
    (none besides the impact)."""
    return r.tie_slack[j] if r.tie[j] == TIE_ELASTIC else 0.0


@njit(cache=True, nogil=True, inline="always")
def tie_levels(r: Regime, ties: TieParams) -> tuple[float, float, bool]:
    """The ties' events ahead in this regime, as levels of s·θ: (the lowest upward one or inf;
    the highest downward one, or 0: none besides the impact; whether the turning point is an
    event: a level that yields unloads there)."""
    up = math.inf
    down = 0.0
    turn = False
    if r.s < 0.0:
        return up, down, turn
    for j in range(ties.levels):
        up = min(up, tie_up_level(r, j, ties))
        down = max(down, tie_down_level(r, j))
        turn = turn or r.tie[j] == TIE_YIELD
    return up, down, turn


@njit(cache=True, nogil=True, inline="always")
def any_tie(r: Regime, state: int, ties: TieParams) -> bool:
    """Whether a tie level is in ``state`` (a TIE_* code)."""
    for j in range(ties.levels):
        if r.tie[j] == state:
            return True
    return False


@njit(cache=True, nogil=True, inline="always")
def ties_left(r: Regime, ties: TieParams) -> bool:
    """Whether a tie level is still anchored (not lost)."""
    for j in range(ties.levels):
        if r.tie[j] != TIE_LOST:
            return True
    return False


@njit(cache=True, nogil=True)
def plastic_elongation(theta: float, r: Regime, j: int, ties: TieParams) -> float:
    """δ_p [m] of tie level j in the regime r at θ: the regime's, or while it yields the
    elongation beyond F_y/k_t (δ_p grows with δ; the regime keeps the value of the last
    yield)."""
    if r.tie[j] == TIE_YIELD and theta > 0.0:
        return max(r.tie_dp[j], ties.height[j] * math.sin(theta) - ties.yield_elongation[j])
    return r.tie_dp[j]


@njit(cache=True, nogil=True)
def plastic_elongations(theta: float, r: Regime, ties: TieParams) -> tuple[float, float]:
    """δ_p [m] of every tie level at θ (:func:`plastic_elongation`; 0 beyond the wall's)."""
    dp = (0.0, 0.0)
    for j in range(ties.levels):
        dp = put(dp, j, plastic_elongation(theta, r, j, ties))
    return dp


@njit(cache=True, nogil=True, inline="always")
def tie_state_at_zero(state: int, dp: float) -> int:
    """A tie level's state when the wall is at θ = 0 (an uplift or an impact): slack with a
    plastic elongation, else elastic (it stretches from θ = 0); lost and no tie stay."""
    if state == TIE_OFF or state == TIE_LOST:
        return state
    return TIE_SLACK if dp > 0.0 else TIE_ELASTIC


@njit(cache=True, nogil=True, inline="always")
def tie_at_zero(r: Regime) -> tuple[int, int]:
    """Every tie level's state at θ = 0 (:func:`tie_state_at_zero`; the levels are filled from
    the first, so a wall whose first is off has none)."""
    if r.tie[0] == TIE_OFF:
        return r.tie
    return (
        tie_state_at_zero(r.tie[0], r.tie_dp[0]),
        tie_state_at_zero(r.tie[1], r.tie_dp[1]),
    )


@njit(cache=True, nogil=True, inline="always")
def acting_bar(r: Regime) -> bool:
    """Whether the bar acting on the side the wall rocks on is intact."""
    return r.intact_pos if r.s > 0.0 else r.intact_neg


@njit(cache=True, nogil=True, inline="always")
def bar_stiffness(r: Regime, prm: KernelParams) -> float:
    """K_s of Eq. 10 in this regime: K while the acting bar is intact, else 0 [-]."""
    return prm.k_bar if acting_bar(r) else 0.0


@njit(cache=True, nogil=True, inline="always")
def rocking_on(r: Regime, s: float, resting: bool) -> Regime:
    """The regime with the side s and the rest flag changed (uplift, impact: θ = 0)."""
    return Regime(
        s, resting, r.intact_pos, r.intact_neg, tie_at_zero(r), r.tie_dp, r.tie_slack, r.tie_yield
    )


@njit(cache=True, nogil=True, inline="always")
def at_rest(r: Regime) -> Regime:
    """The regime of the wall put at rest on its base (its side kept)."""
    return Regime(
        r.s, True, r.intact_pos, r.intact_neg, tie_at_zero(r), r.tie_dp, r.tie_slack, r.tie_yield
    )


@njit(cache=True, nogil=True, inline="always")
def with_bars(r: Regime, intact_pos: bool, intact_neg: bool) -> Regime:
    """The regime with the bars' state changed (rupture)."""
    return Regime(r.s, r.resting, intact_pos, intact_neg, r.tie, r.tie_dp, r.tie_slack, r.tie_yield)


@njit(cache=True, nogil=True)
def record_sample(out: Buffers, k: int, theta: float, omega: float, bar_acting: bool) -> None:
    """Store sample k of the history: θ, θ' and whether an intact bar is stretched."""
    out.theta[k] = theta
    out.omega[k] = omega
    out.bar[k] = 1.0 if bar_acting else 0.0


@njit(cache=True, nogil=True, inline="always")
def record_rupture(out: Buffers, n: int, t: float, s: float) -> None:
    """Store rupture n (from 0) at t [s] on side s, if the buffers have room for it."""
    if n < out.rupture_time.shape[0]:
        out.rupture_time[n] = t
        out.rupture_side[n] = int(s)
