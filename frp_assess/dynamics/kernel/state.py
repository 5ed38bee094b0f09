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
    tie: int  #: the tie's state, a TIE_* code of :mod:`.params` (TIE_OFF: no tie)
    tie_dp: float  #: its plastic elongation δ_p [m]
    tie_slack: float  #: θ where it goes slack, asin(δ_p/h_t) [rad]
    tie_yield: float  #: θ where it yields, asin((δ_p + F_y/k_t)/h_t) [rad] (inf: never)


@njit(cache=True, nogil=True, inline="always")
def initial_regime(theta0: float, omega0: float, prm: KernelParams) -> Regime:
    """The regime of the initial state: at rest when it is (0, 0), the side θ0 (or θ'0) points
    to, every bar intact, the tie (if any) unstretched and elastic from θ = 0 (θ0 > 0 stretches
    it at once: the initial state is the wall's, the tie taken as fitted at θ = 0)."""
    resting = theta0 == 0.0 and omega0 == 0.0
    s = -1.0 if (theta0 < 0.0 or (theta0 == 0.0 and omega0 < 0.0)) else 1.0
    bars = prm.bar_mode != BAR_NONE
    r = Regime(s, resting, bars, bars, TIE_OFF, 0.0, 0.0, math.inf)
    if prm.tie_on:
        r = with_tie(r, TIE_ELASTIC, 0.0, prm)
    return r


@njit(cache=True, nogil=True, inline="always")
def tie_angle(elongation: float, prm: KernelParams) -> float:
    """θ ∈ [0, π/2) at which the tie's elongation h_t·sin θ is ``elongation`` [m] (inf: never)."""
    ratio = elongation / prm.tie_height
    return math.asin(ratio) if ratio < 1.0 else math.inf


@njit(cache=True, nogil=True, inline="always")
def with_tie(r: Regime, state: int, dp: float, prm: KernelParams) -> Regime:
    """The regime with the tie's state and plastic elongation δ_p [m] changed (its levels with
    them)."""
    slack = tie_angle(dp, prm) if dp > 0.0 else 0.0
    yields = tie_angle(dp + prm.tie_yield, prm)
    return Regime(r.s, r.resting, r.intact_pos, r.intact_neg, state, dp, slack, yields)


@njit(cache=True, nogil=True, inline="always")
def tie_terms(r: Regime, prm: KernelParams) -> tuple[float, float]:
    """(t0, t1): the tie's moment over W·R is cos θ·(t0 + t1·sin θ) in this regime (0 on side
    −, slack or lost): elastic, k_t·h_t·(h_t·sin θ − δ_p)/(W·R); yielding, F_y·h_t/(W·R)."""
    if r.s < 0.0 or r.tie == TIE_OFF or r.tie == TIE_SLACK or r.tie == TIE_LOST:
        return 0.0, 0.0
    if r.tie == TIE_YIELD:
        return prm.tie_kn * prm.tie_yield, 0.0
    return -prm.tie_kn * r.tie_dp, prm.tie_kn * prm.tie_height


@njit(cache=True, nogil=True, inline="always")
def tie_levels(r: Regime, prm: KernelParams) -> tuple[float, float, bool]:
    """The tie's events ahead in this regime, as levels of s·θ: (the next upward one — it is
    re-engaged, yields or is lost — or inf; the downward one where it goes slack, or 0: none
    besides the impact; whether the turning point is an event: it unloads from yielding)."""
    if r.s < 0.0 or r.tie == TIE_OFF or r.tie == TIE_LOST:
        return math.inf, 0.0, False
    if r.tie == TIE_SLACK:
        return r.tie_slack, 0.0, False
    if r.tie == TIE_YIELD:
        return math.inf, 0.0, True
    return min(r.tie_yield, prm.tie_theta_loss), r.tie_slack, False


@njit(cache=True, nogil=True)
def plastic_elongation(theta: float, r: Regime, prm: KernelParams) -> float:
    """δ_p [m] in the regime r at θ: the regime's, or while the tie yields the elongation
    beyond F_y/k_t (δ_p grows with δ; the regime keeps the value of the last yield)."""
    if r.tie == TIE_YIELD and theta > 0.0:
        return max(r.tie_dp, prm.tie_height * math.sin(theta) - prm.tie_yield)
    return r.tie_dp


@njit(cache=True, nogil=True, inline="always")
def tie_at_zero(r: Regime) -> int:
    """The tie's state when the wall is at θ = 0 (an uplift or an impact): slack with a
    plastic elongation, else elastic (it stretches from θ = 0); lost and no tie stay."""
    if r.tie == TIE_OFF or r.tie == TIE_LOST:
        return r.tie
    return TIE_SLACK if r.tie_dp > 0.0 else TIE_ELASTIC


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
