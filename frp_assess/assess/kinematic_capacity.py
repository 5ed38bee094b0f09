"""The capacity side of the displacement-based kinematic check (Circolare 2019
§C8.7.1.2.1.2-C8.7.1.2.1.5): the kinematics of the rigid wall rocking about a base corner,
the equivalent SDOF system and the capacity curve a*(d*) of the wall with its bars.

One small function per symbol of the code.  Units: SI (m, s, N, kg); spectral
accelerations a [m/s²]; angles [rad].  Pure numerics, no I/O.  The limit states and the
checks built on this curve are in :mod:`frp_assess.assess.kinematic_nonlinear`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

from frp_assess import libm
from frp_assess.dynamics import Rebars, Wall
from frp_assess.rules.constants import G
from frp_assess.rules.kinematic import RUPTURE_DROP, a_star
from frp_assess.rules.masonry import CONFIDENCE_FACTORS

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
        return (libm.sin(alpha - theta) + stiffness * libm.sin(theta)) / libm.cos(alpha - theta)
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
        d = r * (math.sin(a) - libm.sin(a - th))
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
    return a_star(multiplier, e_star, fc)


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
    fc: float = CONFIDENCE_FACTORS["LC1"],
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
    a = a_star(mult, e_star, fc)
    d = control_displacement(theta, wall)
    return CapacityCurve(wall, k, theta_max, fc, e_star, m_star, d, a, slenderness)
