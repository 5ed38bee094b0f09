"""Displacement-based (nonlinear kinematic) check of the rocking wall with its bars.

Circolare 2019 §C8.7.1.2.1.2-C8.7.1.2.1.9 applied to the rigid wall of docs/model.md: one
block rocking about a base corner, its weight P = w·B·H applied at the centroid, the bars
entering through the internal work of elastic elements (L_i of eq. C8.7.1.1), i.e. the
restoring term K·sin θ of Eq. 10.

Each clause is one small function named after the code's symbol.  Units: SI (m, s, N, kg);
spectral accelerations a [m/s²]; ground accelerations in whatever units the caller uses for
a_g (the ratios do not care); damping ratios as fractions.  Pure numerics, no I/O.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Literal, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import minimize_scalar

from frp_assess.dynamics import Rebars, Wall
from frp_assess.motions import G

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
#: A rupture that leaves less than this fraction of the largest capacity limits d_SLV
#: ("riduzione della capacità ... superiore al 50 % del valore massimo", §C8.7.1.2.1.6) [-].
RUPTURE_DROP = 0.50

#: An elastic displacement spectrum: Sd(T [s], ξ [-]) -> spectral displacement [m].  Both
#: the ground's S_De(T) and the floor's S_eZ·T²/4π² (frp_assess.motions.floor) fit.
DisplacementSpectrum = Callable[[float, float], float]


# --- the kinematics of the rigid wall --------------------------------------------------------


@overload
def static_multiplier(theta: float, alpha: float, stiffness: float = 0.0) -> float: ...
@overload
def static_multiplier(
    theta: NDArray[np.float64], alpha: float, stiffness: float = 0.0
) -> NDArray[np.float64]: ...
def static_multiplier(
    theta: float | NDArray[np.float64], alpha: float, stiffness: float = 0.0
) -> float | NDArray[np.float64]:
    """α(θ) [-]: horizontal load multiplier that holds the wall at rest at the rotation θ.

    Static equilibrium of Eq. 10 (docs/model.md §3.1) with θ'' = 0 and a horizontal inertia
    force α·m·g pushing towards θ > 0, i.e. ü_g = −α·g:

        0 = sin(α_w − θ) − α·cos(α_w − θ) + K·sin θ
        α(θ) = [sin(α_w − θ) + K·sin θ] / cos(α_w − θ)

    At θ = 0 this is α0 = tan α_w = B/H (eq. C8.7.1.1 for one block: the bars, unstressed at
    rest, do no work), and without bars α(θ) = tan(α_w − θ) vanishes at θ = α_w.

    Args:
        theta: rotation θ [rad], 0 ≤ θ < α_w + π/2 (a number or an array).
        alpha: slenderness α_w [rad] of the wall.
        stiffness: K [-] of Eq. 10 (0: unreinforced, or the bar has broken).
    """
    if isinstance(theta, np.ndarray):
        return (np.sin(alpha - theta) + stiffness * np.sin(theta)) / np.cos(alpha - theta)
    return (math.sin(alpha - theta) + stiffness * math.sin(theta)) / math.cos(alpha - theta)


@overload
def control_displacement(theta: float, wall: Wall) -> float: ...
@overload
def control_displacement(theta: NDArray[np.float64], wall: Wall) -> NDArray[np.float64]: ...
def control_displacement(
    theta: float | NDArray[np.float64], wall: Wall
) -> float | NDArray[np.float64]:
    """d_C [m]: horizontal displacement of the centroid (the control point C) at θ [rad].

    The centroid lies R·sin α from the pivot at rest and R·sin(α − θ) after a rotation θ
    about it: d_C = R·[sin α − sin(α − θ)], exact for finite rotations (§C8.7.1.2.1.2 asks
    for the multiplier on the varied configurations).  d_C(α) = R·sin α = B/2.  An infinite
    rotation (a wall that fell) gives an infinite displacement.
    """
    a, r = wall.alpha, wall.R
    if isinstance(theta, np.ndarray):
        th = np.where(np.isfinite(theta), theta, 0.0)
        d = r * (math.sin(a) - np.sin(a - th))
        return np.where(np.isfinite(theta), d, np.inf)
    if not math.isfinite(theta):
        return math.inf
    return r * (math.sin(a) - math.sin(a - theta))


def rotation_at(d_c: float, wall: Wall) -> float:
    """θ [rad] at which the centroid has moved d_C [m], 0 ≤ d_C ≤ R·(1 + sin α); inverse of
    :func:`control_displacement`: θ = α − asin(sin α − d_C/R)."""
    s = math.sin(wall.alpha) - d_c / wall.R
    if not -1.0 <= s <= 1.0:
        raise ValueError(f"control displacement {d_c!r} m is out of the wall's reach")
    return wall.alpha - math.asin(s)


# --- the equivalent SDOF system (Circolare 2019 §C8.7.1.2.1.3) ------------------------------


def _weights(weights: ArrayLike, virtual_dx: ArrayLike) -> tuple[NDArray, NDArray]:
    p = np.asarray(weights, dtype=float).ravel()
    dx = np.asarray(virtual_dx, dtype=float).ravel()
    if p.size == 0 or p.shape != dx.shape:
        raise ValueError("weights and virtual displacements must be equal, non-empty lists")
    if np.any(p <= 0.0) or not np.all(np.isfinite(p)) or not np.all(np.isfinite(dx)):
        raise ValueError("weights must be > 0 and virtual displacements finite")
    if not np.any(dx != 0.0):
        raise ValueError("the virtual displacements cannot all be zero")
    return p, dx


def participating_mass_fraction(weights: ArrayLike, virtual_dx: ArrayLike) -> float:
    """e* = (Σ P_k·δ_k)² / (Σ P_k · Σ P_k·δ_k²) [-] (Circolare 2019 eq. C8.7.1.5).

    Args:
        weights: P_k + Q_k [N], the weights whose masses move with block k.
        virtual_dx: δ_PQx,k, virtual horizontal displacements of their centroids (any unit).
    """
    p, dx = _weights(weights, virtual_dx)
    return float(np.sum(p * dx) ** 2 / (np.sum(p) * np.sum(p * dx * dx)))


def participating_mass(weights: ArrayLike, virtual_dx: ArrayLike) -> float:
    """M* = (Σ P_k·δ_k)² / (g·Σ P_k·δ_k²) = e*·Σ P_k/g [kg] (the mass of the equivalent
    oscillator behind eq. C8.7.1.5 of Circolare 2019; eq. C8A.4.2 of Circolare 2009).

    Args: as :func:`participating_mass_fraction`, weights in N.
    """
    p, dx = _weights(weights, virtual_dx)
    return float(np.sum(p * dx) ** 2 / (G * np.sum(p * dx * dx)))


def spectral_displacement(
    d_c: float, weights: ArrayLike, virtual_dx: ArrayLike, virtual_dx_control: float
) -> float:
    """d = d_C·Σ P_k·δ_k² / (δ_Cx·Σ P_k·δ_k) [units of d_C] (Circolare 2019 eq. C8.7.1.4).

    Args:
        d_c: displacement of the control point C [m].
        weights, virtual_dx: as :func:`participating_mass_fraction`.
        virtual_dx_control: δ_Cx, virtual horizontal displacement of C (same unit as δ_k).
    """
    p, dx = _weights(weights, virtual_dx)
    if not (math.isfinite(virtual_dx_control) and virtual_dx_control != 0.0):
        raise ValueError("the control point's virtual displacement must be finite and non-zero")
    return float(d_c * np.sum(p * dx * dx) / (virtual_dx_control * np.sum(p * dx)))


def spectral_acceleration(multiplier: float, e_star: float, fc: float) -> float:
    """a = α·g/(e*·FC) [m/s²] (Circolare 2019 eq. C8.7.1.3; FC applies to the capacity).

    Args:
        multiplier: α(d_C) [-].
        e_star: e* [-].
        fc: confidence factor FC [-] (LC1's 1.35 when the masonry's compressive strength is
            not used, as for a rigid block, §C8.7.1.2.1.3).
    """
    if not (e_star > 0.0 and fc > 0.0):
        raise ValueError(f"e* and FC must be > 0, got {e_star!r}, {fc!r}")
    return multiplier * G / (e_star * fc)


# --- the capacity curve of the wall with its bars ---------------------------------------------


@dataclass(frozen=True)
class CapacityCurve:
    """Capacity curve a(d) of the equivalent SDOF system of one wall and its bars.

    One block, its weight at the centroid, the centroid as control point: e* = 1, M* = m and
    d = d_C (eqs. C8.7.1.3-C8.7.1.5).  The arrays run from θ = 0 to θ = α (the bare wall's
    d0); a rupture of the bars inside that range appears as two points at the same d.

    ``slenderness`` is the α of the restoring moment of the model the IDA runs (tan α = a_RM/g:
    the block's B/H at its edge, (B − x)/H with the base reaction moved inward by x/2); None:
    the wall's own α.  The block turns about its base corner, so d_C(θ) keeps the wall's
    geometry (:func:`control_displacement`) while the moment balance uses ``slenderness``.
    """

    wall: Wall
    stiffness: float  #: K of Eq. 10 while the bar is intact [-] (0 unreinforced)
    rupture_rotation: float  #: θ_max [rad] (inf: no bar, or it cannot break)
    fc: float  #: confidence factor FC [-]
    e_star: float  #: e* [-]
    m_star: float  #: M* [kg per metre of wall]
    d: NDArray[np.float64]  #: spectral displacement d [m]
    a: NDArray[np.float64]  #: spectral acceleration a [m/s²]
    slenderness: float | None = None  #: α of the restoring moment [rad]; None: the wall's

    @property
    def alpha(self) -> float:
        """α [rad] of the restoring moment: θ where the bare wall's capacity vanishes."""
        return self.wall.alpha if self.slenderness is None else self.slenderness

    @property
    def d0(self) -> float:
        """d0 [m]: where a = 0 on the curve of the actions surely present up to collapse, the
        bare wall's (brittle bars do not last to collapse, §C8.7.1.2.1.6): d_C(α), R·sin α =
        B/2 for the block about its edge."""
        return control_displacement(self.alpha, self.wall)

    @property
    def a0(self) -> float:
        """a0* = α0·g/(e*·FC) [m/s²], the spectral acceleration that activates rocking
        (α0 = tan α: the bars, unstressed at rest, do not change it)."""
        return spectral_acceleration(math.tan(self.alpha), self.e_star, self.fc)

    @property
    def rupture_displacement(self) -> float:
        """d [m] at which the acting bar breaks (inf if it never does before θ = α)."""
        if self.rupture_rotation >= self.alpha:
            return math.inf
        return control_displacement(self.rupture_rotation, self.wall)

    def a_at(self, d: float) -> float:
        """a(d) [m/s²] on the curve, with the bar if it is intact at d (at the rupture
        displacement itself the bar still holds: the value just before it breaks)."""
        theta = rotation_at(d, self.wall)
        k = self.stiffness if d <= self.rupture_displacement else 0.0
        return spectral_acceleration(static_multiplier(theta, self.alpha, k), self.e_star, self.fc)

    @property
    def a_max(self) -> float:
        """Largest spectral acceleration of the curve [m/s²]."""
        return float(np.max(self.a))

    @property
    def rupture_limit(self) -> float:
        """Displacement [m] at which a rupture of the bars drops the capacity below
        (1 − 0.50) of its largest value (second criterion for d_SLV, §C8.7.1.2.1.6); inf if
        the bars do not break before d0 or the drop is smaller."""
        d_r = self.rupture_displacement
        if not math.isfinite(d_r):
            return math.inf
        after = spectral_acceleration(
            static_multiplier(self.rupture_rotation, self.alpha, 0.0), self.e_star, self.fc
        )
        return d_r if after < (1.0 - RUPTURE_DROP) * self.a_max else math.inf


def capacity_curve(
    wall: Wall,
    rebars: Rebars | None = None,
    *,
    fc: float = 1.35,
    points: int = 401,
    slenderness: float | None = None,
    stiffness: float | None = None,
    rupture_rotation: float | None = None,
) -> CapacityCurve:
    """The capacity curve a(d) of the wall and its bars (Circolare 2019 §C8.7.1.2.1.2-3).

    α(θ) from the static equilibrium of Eq. 10 (:func:`static_multiplier`) with K while the
    bar is intact and 0 after it breaks at θ_max (Eq. 11); a = α·g/(e*·FC); d = d_C.

    Args:
        wall: the wall.
        rebars: its bars (None: unreinforced).
        fc: confidence factor FC [-].
        points: number of rotations sampled in [0, α].
        slenderness, stiffness, rupture_rotation: α [rad], K [-] and θ_max [rad] of the
            model the IDA runs (:func:`frp_assess.assess.kinematic_checks.model_capacity_curve`
            passes the model's); None: the paper's values of the block about its edge.
    """
    if points < 2:
        raise ValueError(f"need at least 2 points, got {points!r}")
    k = (
        stiffness
        if stiffness is not None
        else (0.0 if rebars is None else rebars.stiffness_term(wall))
    )
    theta_max = rupture_rotation
    if theta_max is None:
        theta_max = math.inf if rebars is None else rebars.rupture_rotation(wall)
    alpha = wall.alpha if slenderness is None else slenderness
    e_star = participating_mass_fraction([1.0], [1.0])  # one block: e* = 1
    m_star = participating_mass([wall.mass * G], [1.0])  # = m
    theta = np.linspace(0.0, alpha, points)
    if theta_max < alpha:
        theta = np.sort(np.concatenate([theta[theta != theta_max], [theta_max, theta_max]]))
    intact = np.ones(theta.size, dtype=bool)
    if theta_max < alpha:
        intact = theta < theta_max
        intact[np.searchsorted(theta, theta_max)] = True  # the first of the two rupture points
    mult = np.where(intact, static_multiplier(theta, alpha, k), static_multiplier(theta, alpha))
    a = mult * G / (e_star * fc)
    d = control_displacement(theta, wall)
    return CapacityCurve(wall, k, theta_max, fc, e_star, m_star, d, a, slenderness)


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
