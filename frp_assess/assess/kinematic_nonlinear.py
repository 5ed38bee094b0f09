"""Displacement-based (nonlinear kinematic) check of the rocking wall with its bars.

Circolare 2019 §C8.7.1.2.1.2-C8.7.1.2.1.9 applied to the rigid wall of docs/model.md: one
block rocking about a base corner, its weight P = w·B·H applied at the centroid, the bars
entering through the internal work of elastic elements (L_i of eq. C8.7.1.1), i.e. the
restoring term K·sin θ of Eq. 10.

Each clause is one small function named after the code's symbol.  Units: SI (m, s, N, kg);
spectral accelerations a [m/s²]; ground accelerations in whatever units the caller uses for
a_g (the ratios do not care); damping ratios as fractions.  Pure numerics, no I/O.

The kinematics, the equivalent SDOF system and the capacity curve are in
:mod:`frp_assess.assess.kinematic_capacity` (its names used by the kinematic checks are
re-exported here); this module holds the limit states and the checks built on the curve.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Literal, Protocol, runtime_checkable

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import minimize_scalar

from frp_assess.assess.kinematic_capacity import CapacityCurve as CapacityCurve  # re-export
from frp_assess.assess.kinematic_capacity import capacity_curve as capacity_curve  # re-export
from frp_assess.assess.kinematic_capacity import (
    control_displacement as control_displacement,  # re-export
)

LimitState = Literal["SLV", "SLC"]

#: Equivalent viscous damping of the mechanism (Circolare 2019 §C8.7.1.2.1.8) [-].
XI_SLV = 0.08
XI_SLC = 0.10
#: Fractions of d0 that bound d_SLV and d_SLC (Circolare 2019 §C8.7.1.2.1.6) [-].
D0_FRACTION_SLV = 0.40
D0_FRACTION_SLC = 0.60
#: Coefficients of the secant periods, eqs. C8.7.1.10 and C8.7.1.11 [-].
PERIOD_FACTOR_SLV = 1.68
PERIOD_FACTOR_SLC = 1.56

#: An elastic displacement spectrum: Sd(T [s], ξ [-]) -> spectral displacement [m].  Both
#: the ground's S_De(T) and the floor's S_eZ·T²/4π² (frp_assess.motions.floor) fit.
DisplacementSpectrum = Callable[[float, float], float]


@runtime_checkable
class SampledSpectrum(Protocol):
    """A :data:`DisplacementSpectrum` that also gives Sd at many periods in one call, with
    the same values (the code spectra of :mod:`frp_assess.assess.check_demand`)."""

    def __call__(self, period: float, damping: float) -> float: ...

    def at(self, periods: NDArray[np.float64], damping: float) -> NDArray[np.float64]:
        """Sd [m] at each of ``periods`` [s], damping ξ [-]."""
        ...


# --- the limit states (Circolare 2019 §C8.7.1.2.1.6 and .8) ------------------------------------


def d_slv(d0: float, d_rupture: float = math.inf) -> float:
    """d_SLV = min(0.40·d0, d where a rupture drops the capacity by more than 50 %) [m]
    (Circolare 2019 §C8.7.1.2.1.6)."""
    return min(D0_FRACTION_SLV * d0, d_rupture)


def d_slc(d0: float, d_instability: float = math.inf) -> float:
    """d_SLC = min(0.60·d0, d of a local instability, where it can be assessed) [m]
    (Circolare 2019 §C8.7.1.2.1.6: the text's second SLC criterion is a situation locally
    incompatible with the stability of the building's elements, e.g. beams sliding off, not
    the rupture of ties, which is an SLV criterion)."""
    return min(D0_FRACTION_SLC * d0, d_instability)


def _secant_period(factor: float, d: float, a: float) -> float:
    if not (d > 0.0 and a > 0.0):
        raise ValueError(f"the secant period needs d > 0 and a(d) > 0, got {d!r}, {a!r}")
    return factor * math.pi * math.sqrt(d / a)


def t_slv(d: float, a: float) -> float:
    """T_SLV = 1.68·π·√(d_SLV/a(d_SLV)) [s], d [m], a [m/s²] (Circolare 2019 eq. C8.7.1.10)."""
    return _secant_period(PERIOD_FACTOR_SLV, d, a)


def t_slc(d: float, a: float) -> float:
    """T_SLC = 1.56·π·√(d_SLC/a(d_SLC)) [s], d [m], a [m/s²] (Circolare 2019 eq. C8.7.1.11)."""
    return _secant_period(PERIOD_FACTOR_SLC, d, a)


def displacement_demand(
    sd: DisplacementSpectrum, period: float, damping: float, *, t0: float = 0.0, samples: int = 200
) -> float:
    """Displacement demand [m]: the largest Sd(T, ξ) over T in [T0, T_s] (Circolare 2019
    §C8.7.1.2.1.8; for a spectrum that grows with T it is Sd(T_s, ξ), as the code spectra
    and eq. C8.7.1.12 give).

    Args:
        sd: elastic displacement spectrum Sd(T [s], ξ [-]) [m] at the design intensity.
        period: T_SLV or T_SLC [s].
        damping: ξ [-] (8 % SLV, 10 % SLC).
        t0: T0 [s], the initial period of the mechanism (0 for a rigid block).
        samples: periods sampled in [T0, T_s] (T_s itself always included); the largest
            sample is refined by a bounded scalar search in the intervals next to it.
    """
    if not (0.0 <= t0 <= period and math.isfinite(period)):
        raise ValueError(f"need 0 <= T0 <= T_s, got T0 = {t0!r}, T_s = {period!r}")
    periods = np.linspace(t0, period, max(samples, 3))
    if isinstance(sd, SampledSpectrum):  # the same values, one call (the checks' hot spot)
        values = [float(v) for v in sd.at(periods, damping)]
    else:
        values = [float(sd(float(T), damping)) for T in periods]
    i = int(np.argmax(values))
    lo, hi = periods[max(i - 1, 0)], periods[min(i + 1, periods.size - 1)]
    if hi <= lo:
        return values[i]
    # a peak between samples (a record's spectrum): refine in the two intervals around it
    best = minimize_scalar(
        lambda T: -float(sd(float(T), damping)),
        bounds=(float(lo), float(hi)),
        method="bounded",
        options={"xatol": 1e-9 * max(period, 1.0)},
    )
    return max(values[i], -float(best.fun))


def a_g_sld(a0_star: float, floor_ratio: float = 1.0) -> float:
    """a_g,SLD [units of a0*]: the ground acceleration at which the floor's peak acceleration
    a_Z reaches a0* (Circolare 2019 eq. C8.7.1.8, a_Z,SLD = α0·g/(e*·FC)).

    Args:
        a0_star: a0* = α0·g/(e*·FC).
        floor_ratio: a_Z per unit ground acceleration [-] (1 at ground level, in a_g·S terms).
    """
    if not floor_ratio > 0.0:
        raise ValueError(f"floor ratio must be > 0, got {floor_ratio!r}")
    return a0_star / floor_ratio


def a_g_limit(
    a_g: float, capacity: float, demand: float, a_g_sld_value: float | None = None
) -> float:
    """a_g,SLV (or a_g,SLC) [units of a_g]: the ground acceleration whose displacement demand
    equals the capacity, a_g·d_lim/D(a_g), not less than a_g,SLD (Circolare 2019
    §C8.7.1.2.1.8, below eq. C8.7.1.12).

    The demand is taken as proportional to a_g (the spectrum's shape kept, as for the floor
    spectrum, which is linear in the ground spectrum).

    Args:
        a_g: the design intensity the demand was computed for (any units, e.g. a_g·S in g).
        capacity: d_SLV or d_SLC [m].
        demand: D [m] at a_g.
        a_g_sld_value: a_g,SLD in the units of a_g (None: no floor).
    """
    if not (capacity > 0.0 and demand > 0.0 and a_g > 0.0):
        raise ValueError("a_g, capacity and demand must be > 0")
    value = a_g * capacity / demand
    return value if a_g_sld_value is None else max(value, a_g_sld_value)


def zeta_e(capacity: float, demand: float) -> float:
    """ζ_E = capacity / demand [-], in PGA terms (a_g,SLV / a_g, or a_dyn/(FC·a_g·S))."""
    if not (capacity >= 0.0 and demand > 0.0):
        raise ValueError(f"need capacity >= 0 and demand > 0, got {capacity!r}, {demand!r}")
    return capacity / demand


@dataclass(frozen=True)
class LimitStateCheck:
    """The displacement-based check of one limit state (Circolare 2019 §C8.7.1.2.1.8)."""

    limit_state: LimitState
    d_limit: float  #: d_SLV or d_SLC [m]
    a_limit: float  #: a(d_limit) [m/s²]
    period: float  #: T_SLV or T_SLC [s]
    damping: float  #: ξ of the mechanism [-]
    demand: float  #: displacement demand at the design intensity [m]
    a_g: float  #: the design intensity (units of the caller)
    a_g_capacity: float  #: a_g,SLV or a_g,SLC [units of a_g]

    @property
    def zeta_e(self) -> float:
        """ζ_E = a_g,lim / a_g [-]."""
        return zeta_e(self.a_g_capacity, self.a_g)

    @property
    def passed(self) -> bool:
        return self.a_g_capacity >= self.a_g


def limit_state_check(
    curve: CapacityCurve,
    limit_state: LimitState,
    sd: DisplacementSpectrum,
    a_g: float,
    *,
    a_g_sld_value: float | None = None,
    t0: float = 0.0,
) -> LimitStateCheck:
    """The SLV or SLC displacement check of a capacity curve against a displacement spectrum.

    SLV: d_SLV = min(0.40·d0, rupture limit), T_SLV (eq. C8.7.1.10), ξ = 8 %.
    SLC: d_SLC = 0.60·d0, T_SLC (eq. C8.7.1.11), ξ = 10 %.

    Args:
        curve: the capacity curve.
        limit_state: ``"SLV"`` or ``"SLC"``.
        sd: elastic displacement spectrum Sd(T, ξ) [m] at the intensity a_g of that state.
        a_g: that intensity (e.g. a_g·S [g]).
        a_g_sld_value: a_g,SLD in the units of a_g (the SLV value is not taken below it).
        t0: initial period of the mechanism [s] (0 for a rigid block).
    """
    if limit_state == "SLV":
        d_lim = d_slv(curve.d0, curve.rupture_limit)
        period = t_slv(d_lim, curve.a_at(d_lim))
        damping = XI_SLV
    elif limit_state == "SLC":
        d_lim = d_slc(curve.d0)
        period = t_slc(d_lim, curve.a_at(d_lim))
        damping = XI_SLC
    else:
        raise ValueError(f"limit state must be 'SLV' or 'SLC', got {limit_state!r}")
    demand = displacement_demand(sd, period, damping, t0=t0)
    capacity = a_g_limit(a_g, d_lim, demand, a_g_sld_value)
    return LimitStateCheck(
        limit_state, d_lim, curve.a_at(d_lim), period, damping, demand, a_g, capacity
    )


# --- the time-history check (Circolare 2019 §C8.7.1.2.1.9) ------------------------------------


@dataclass(frozen=True)
class TimeHistoryCheck:
    """Peak displacements of the records scaled to the design intensity against d0 and d_lim."""

    peaks: tuple[float, ...]  #: peak displacement of each record [m] (inf: the wall fell)
    d0: float  #: [m]
    d_limit: float  #: d_SLV or d_SLC [m]

    @property
    def max_peak(self) -> float:
        return max(self.peaks)

    @property
    def mean_peak(self) -> float:
        """Mean of the peak displacements [m] (inf if a wall fell)."""
        return math.fsum(self.peaks) / len(self.peaks)

    @property
    def d0_respected(self) -> bool:
        """No record exceeds d0."""
        return self.max_peak <= self.d0

    @property
    def mean_respected(self) -> bool:
        """The mean peak does not exceed d_lim."""
        return self.mean_peak <= self.d_limit

    @property
    def passed(self) -> bool:
        return self.d0_respected and self.mean_respected

    @property
    def ratio(self) -> float:
        """d_lim / mean peak [-] (capacity over demand in displacement; 0 if a wall fell)."""
        mean = self.mean_peak
        return math.inf if mean == 0.0 else self.d_limit / mean

    @property
    def margin(self) -> float | None:
        """The number that decides the check: min(d_lim/mean peak, d0/largest peak) [-],
        ≥ 1 when both conditions hold (:attr:`passed`); 0 if a record made the wall fall;
        None if no record made it rock (nothing to compare)."""
        worst = self.max_peak
        if not math.isfinite(worst):
            return 0.0
        if worst == 0.0:
            return None
        return min(self.d_limit / self.mean_peak, self.d0 / worst)


def time_history_check(peaks: Sequence[float], d0: float, d_limit: float) -> TimeHistoryCheck:
    """Circolare 2019 §C8.7.1.2.1.9: the limit state is met if no record's peak displacement
    exceeds d0 and the mean of the peaks does not exceed d_SLV (or d_SLC).

    Args:
        peaks: peak displacement of the control point under each record scaled to the design
            intensity [m] (:func:`control_displacement` of the peak rotation; inf if it fell).
        d0: [m].
        d_limit: d_SLV or d_SLC [m].
    """
    values = tuple(float(p) for p in peaks)
    if not values:
        raise ValueError("the time-history check needs at least one record")
    if any(math.isnan(p) or p < 0.0 for p in values):
        raise ValueError("peak displacements must be >= 0")
    if not (0.0 < d_limit <= d0):
        raise ValueError(f"need 0 < d_limit <= d0, got {d_limit!r}, {d0!r}")
    return TimeHistoryCheck(values, d0, d_limit)
