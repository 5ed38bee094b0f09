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
from frp_assess.rules.kinematic import D0_FRACTION_SLC as D0_FRACTION_SLC
from frp_assess.rules.kinematic import D0_FRACTION_SLV as D0_FRACTION_SLV
from frp_assess.rules.kinematic import PERIOD_FACTOR_SLC as PERIOD_FACTOR_SLC
from frp_assess.rules.kinematic import PERIOD_FACTOR_SLV as PERIOD_FACTOR_SLV
from frp_assess.rules.kinematic import XI_SLC as XI_SLC

# the clauses of the limit states, written once in rules/ (re-exported)
from frp_assess.rules.kinematic import XI_SLV as XI_SLV
from frp_assess.rules.kinematic import a_g_limit as a_g_limit
from frp_assess.rules.kinematic import a_g_sld as a_g_sld
from frp_assess.rules.kinematic import d_slc as d_slc
from frp_assess.rules.kinematic import d_slv as d_slv
from frp_assess.rules.kinematic import t_slc as t_slc
from frp_assess.rules.kinematic import t_slv as t_slv
from frp_assess.rules.kinematic import zeta_e as zeta_e

LimitState = Literal["SLV", "SLC"]

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


# --- the displacement demand (Circolare 2019 §C8.7.1.2.1.8) --------------------------------------


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
