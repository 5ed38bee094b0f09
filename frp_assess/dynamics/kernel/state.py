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

from typing import NamedTuple

import numpy as np
from numba import njit

from frp_assess.dynamics.kernel.params import BAR_NONE, KernelParams


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


@njit(cache=True, nogil=True, inline="always")
def initial_regime(theta0: float, omega0: float, prm: KernelParams) -> Regime:
    """The regime of the initial state: at rest when it is (0, 0), the side θ0 (or θ'0) points
    to, every bar intact."""
    resting = theta0 == 0.0 and omega0 == 0.0
    s = -1.0 if (theta0 < 0.0 or (theta0 == 0.0 and omega0 < 0.0)) else 1.0
    bars = prm.bar_mode != BAR_NONE
    return Regime(s, resting, bars, bars)


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
    """The regime with the side s and the rest flag changed (uplift, impact)."""
    return Regime(s, resting, r.intact_pos, r.intact_neg)


@njit(cache=True, nogil=True, inline="always")
def at_rest(r: Regime) -> Regime:
    """The regime of the wall put at rest on its base (its side kept)."""
    return Regime(r.s, True, r.intact_pos, r.intact_neg)


@njit(cache=True, nogil=True, inline="always")
def with_bars(r: Regime, intact_pos: bool, intact_neg: bool) -> Regime:
    """The regime with the bars' state changed (rupture)."""
    return Regime(r.s, r.resting, intact_pos, intact_neg)


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
