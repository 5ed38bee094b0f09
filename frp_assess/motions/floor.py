"""The motion of a floor of the building and the code's floor spectrum (first mode only).

A wall whose rocking base stands at the height Z above the foundation is shaken by the
absolute acceleration of that floor, not by the ground.  Two models are given here:

* the **time history** a_floor(t) = ü_g(t) + γ1·ψ1(Z)·D̈1(t), where D̈1 is the relative
  acceleration of a linear oscillator of the building's first period T1 and damping ξ1 under
  the ground acceleration ü_g, γ1 = 3n/(2n+1) (Circolare 2019 eq. C7.2.10) and ψ1(Z) = Z/H_b
  is the linear first mode normalised to 1 at the top that eq. C7.2.10 assumes;
* the **code floor spectrum** S_eZ(T, ξ, z) of Circolare 2019 §C7.2.3, eqs. C7.2.5-C7.2.9
  (a = 0.8, b = 1.1, first mode only, as §C7.2.3 allows for local mechanisms), and the floor
  displacement spectrum of §C8.7.1.2.1.8 (eq. C8.7.1.12: S_eZ·T²/4π², not decreasing beyond
  b·T1).

Units: accelerations of the time histories in whatever units the input has; spectral
accelerations in g; displacement spectra in m; periods in s; damping ratios as fractions
(0.05 for 5 %).  Pure numerics: no I/O.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numba import njit
from numpy.typing import ArrayLike, NDArray

from frp_assess import libm
from frp_assess.motions.record import G, kernel_record
from frp_assess.motions.response import _coefficients
from frp_assess.motions.spectra import ElasticSpectrum, damping_correction, ec8_shape

#: Ends of the plateau of the floor spectrum, as fractions of T1 (Circolare 2019 §C7.2.3,
#: the values the text gives for eqs. C7.2.6).
FLOOR_PLATEAU_A = 0.8
FLOOR_PLATEAU_B = 1.1
#: Masonry and any other structure: C1 of Circolare 2019 eq. C7.3.2, T1 = C1·H^(3/4).
C1_MASONRY = 0.050

#: An elastic ground spectrum as a function: Se(T [s], ξ [-]) -> spectral acceleration [g].
GroundSpectrum = Callable[[NDArray[np.float64], float], NDArray[np.float64]]


# --- the floor motion ----------------------------------------------------------------------


@njit(cache=True, nogil=True)
def _relative_acceleration(acc: np.ndarray, dt: float, period: float, xi: float) -> np.ndarray:
    """ü_rel(t_i) of the oscillator (T, ξ) starting at rest, at the samples of ``acc``.

    The recurrence of :mod:`frp_assess.motions.response` (exact for a ground acceleration
    linear between samples) gives u and u̇ at every sample; the equation of motion then gives
    ü_rel = −ü_g − 2ξω·u̇ − ω²·u there, exactly.
    """
    n = acc.size
    out = np.empty(n)
    if n == 0:
        return out
    omega = 2.0 * math.pi / period
    a, b, c, d, ap, bp, cp, dp = _coefficients(omega, xi, dt)
    two_xi_omega = 2.0 * xi * omega
    omega2 = omega * omega
    u = 0.0
    v = 0.0
    out[0] = -acc[0]
    for i in range(n - 1):
        p0 = -acc[i]
        p1 = -acc[i + 1]
        un = a * u + b * v + c * p0 + d * p1
        vn = ap * u + bp * v + cp * p0 + dp * p1
        u = un
        v = vn
        out[i + 1] = -acc[i + 1] - two_xi_omega * v - omega2 * u
    return out


def participation_factor(storeys: int) -> float:
    """γ1 = 3n/(2n+1) [-]: first-mode participation factor of an n-storey building with
    uniform mass and a linear first mode normalised to 1 at the top (Circolare 2019
    §C7.2.3, eq. C7.2.10)."""
    if isinstance(storeys, bool) or not isinstance(storeys, int) or storeys < 1:
        raise ValueError(f"number of storeys must be an integer >= 1, got {storeys!r}")
    return 3.0 * storeys / (2.0 * storeys + 1.0)


def mode_shape(wall_base: float, height_building: float) -> float:
    """ψ1(Z) = Z/H_b [-]: the linear first mode at the height Z [m] of a building H_b [m] tall
    (normalised to 1 at the top, the mode eq. C7.2.10 of Circolare 2019 assumes)."""
    if not (math.isfinite(height_building) and height_building > 0.0):
        raise ValueError(f"building height must be > 0 m, got {height_building!r}")
    if not (math.isfinite(wall_base) and 0.0 <= wall_base <= height_building):
        raise ValueError(
            f"wall base height must be in [0, {height_building:g}] m, got {wall_base!r}"
        )
    return wall_base / height_building


def default_period(height_building: float) -> float:
    """T1 = C1·H_b^(3/4) [s] with C1 = 0.050 (masonry and any other structure), H_b [m].

    Clause verified: Circolare 2019 §C7.3.3.2, eq. C7.3.2 ("in via di prima
    approssimazione"; C1 = 0.085 steel or timber frames, 0.075 concrete frames, 0.050 masonry
    or any other structure).  NTC 2018 eq. 7.3.6 (§7.3.3.2) is instead T1 = 2·√d from the
    top displacement d under the horizontal load combination [2.5.7], which needs a model of
    the building; the C1·H^(3/4) form was NTC 2008 eq. 7.3.5.
    """
    if not (math.isfinite(height_building) and height_building > 0.0):
        raise ValueError(f"building height must be > 0 m, got {height_building!r}")
    return C1_MASONRY * height_building**0.75


def _check_oscillator(period: float, damping: float) -> None:
    if not (math.isfinite(period) and period > 0.0):
        raise ValueError(f"building period must be > 0 s, got {period!r}")
    if not (math.isfinite(damping) and 0.0 <= damping < 1.0):
        raise ValueError(f"building damping ratio must be in [0, 1), got {damping!r}")


def floor_acceleration(
    acc: ArrayLike,
    dt: float,
    *,
    height_building: float,
    storeys: int,
    wall_base: float,
    period: float,
    damping: float = 0.05,
) -> NDArray[np.float64]:
    """Absolute acceleration of the floor at Z: a(t) = ü_g(t) + γ1·ψ1(Z)·D̈1(t) [units of acc].

    D̈1 is the relative acceleration of a linear oscillator of period T1 and damping ξ1 under
    the ground acceleration, from the exact piecewise-linear recurrence (Nigam & Jennings
    1969), starting at rest; γ1 = 3n/(2n+1) and ψ1(Z) = Z/H_b (Circolare 2019 §C7.2.3,
    eq. C7.2.10 and the linear first mode it assumes).  At Z = 0 the ground record is
    returned unchanged.

    Args:
        acc: ground acceleration samples (any units), the first at t = 0, linear in between.
        dt: sampling interval [s].
        height_building: H_b [m], height of the building above the foundation.
        storeys: n [-], number of storeys.
        wall_base: Z [m], height of the wall's rocking base above the foundation, 0 ≤ Z ≤ H_b.
        period: T1 [s], fundamental period of the building.
        damping: ξ1 [-], damping ratio of the building's first mode (default 5 %).
    """
    gamma = participation_factor(storeys)
    psi = mode_shape(wall_base, height_building)
    _check_oscillator(period, damping)
    if not (math.isfinite(dt) and dt > 0.0):
        raise ValueError(f"dt must be > 0 s, got {dt!r}")
    ground = kernel_record(np.ravel(acc))
    if psi == 0.0:
        return ground.copy()
    rel = _relative_acceleration(ground, float(dt), float(period), float(damping))
    return ground + gamma * psi * rel


# --- the code's floor spectrum -------------------------------------------------------------


def ground_spectrum_function(spectrum: ElasticSpectrum) -> GroundSpectrum:
    """Se(T, ξ) [g] of a target spectrum at any damping ratio ξ [-].

    Code shapes (EC8, NTC 2018) are rebuilt with η(ξ) of NTC 2018 eq. 3.2.4 (EN 1998-1
    eq. 3.6); a table spectrum, given at its own damping, is multiplied by η(ξ)/η(table).
    """
    if spectrum.table is not None:
        periods = np.asarray(spectrum.table[0])
        values = np.asarray(spectrum.table[1])

        def table(T: NDArray[np.float64], xi: float) -> NDArray[np.float64]:
            scale = damping_correction(xi) / spectrum.eta
            return np.interp(np.asarray(T, dtype=float), periods, values) * scale

        return table
    t_b, t_c, t_d = spectrum.T_B, spectrum.T_C, spectrum.T_D
    assert t_b is not None and t_c is not None and t_d is not None

    def shape(T: NDArray[np.float64], xi: float) -> NDArray[np.float64]:
        eta = damping_correction(xi)
        return ec8_shape(T, spectrum.pga_g, t_b, t_c, t_d, eta, spectrum.plateau_factor)

    return shape


def floor_peak_acceleration(
    se_t1: float, *, storeys: int, z_over_h: float, building_damping: float = 0.05
) -> float:
    """a_Z,1(z) = S_e(T1, ξ1)·|γ1·ψ1(z)|·√(1 + 0.0004·ξ1²) [units of se_t1, g].

    Circolare 2019 §C7.2.3, eq. C7.2.7 for the first mode (eq. C7.2.8 with one mode), with
    γ1 of eq. C7.2.10 and ψ1(z) = z/H.  ξ1 enters the square root in percent (the text's
    unit): √(1 + 0.0004·ξ1[%]²) = √(1 + 4·ξ1²) with ξ1 as a fraction.

    Args:
        se_t1: S_e(T1, ξ1), the elastic ground spectrum at the building's period and damping.
        storeys: n [-].
        z_over_h: z/H [-], 0 ≤ z/H ≤ 1.
        building_damping: ξ1 [-] (fraction).
    """
    if not (math.isfinite(z_over_h) and 0.0 <= z_over_h <= 1.0):
        raise ValueError(f"z/H must be in [0, 1], got {z_over_h!r}")
    xi_percent = 100.0 * building_damping
    return (
        se_t1
        * abs(participation_factor(storeys) * z_over_h)
        * math.sqrt(1.0 + 0.0004 * xi_percent**2)
    )


def floor_amplification(building_damping: float, damping: float) -> float:
    """1.1·ξ1^(-0.5)·η(ξ) [-]: peak of the floor spectrum over a_Z,1 (Circolare 2019 eq. C7.2.9).

    ξ1 is taken here as a fraction (5 % -> 0.05 gives 1.1/√0.05 = 4.92): with ξ1 in percent
    the factor would be 0.49 at 5 %, below the floor's own peak acceleration, which the
    spectrum equals at T = 0, so that reading cannot be the intended one.  η(ξ) is NTC 2018
    eq. 3.2.4 for the element's damping ξ.
    """
    if not (math.isfinite(building_damping) and 0.0 < building_damping < 1.0):
        raise ValueError(f"building damping ratio must be in (0, 1), got {building_damping!r}")
    return 1.1 * building_damping**-0.5 * damping_correction(damping)


def floor_spectrum(
    periods: ArrayLike,
    ground: GroundSpectrum,
    *,
    period: float,
    storeys: int,
    z_over_h: float,
    building_damping: float = 0.05,
    damping: float = 0.05,
    a: float = FLOOR_PLATEAU_A,
    b: float = FLOOR_PLATEAU_B,
) -> NDArray[np.float64]:
    """S_eZ(T, ξ, z) [g]: the floor acceleration spectrum of Circolare 2019 §C7.2.3, first mode.

    With A = 1.1·ξ1^(-0.5)·η(ξ) (eq. C7.2.9) and a_Z = a_Z,1(z) (eq. C7.2.7), eq. C7.2.6:

        T < a·T1:         A·a_Z / [1 + (A − 1)·(1 − T/(a·T1))^1.6]
        a·T1 ≤ T < b·T1:  A·a_Z
        T ≥ b·T1:         A·a_Z / [1 + (A − 1)·(T/(b·T1) − 1)^1.2]

    and eq. C7.2.5 (one mode): S_eZ = |S_eZ,1|, not less than the ground spectrum Se(T, ξ)
    for T > T1.  At z = 0 the first-mode formula vanishes below T1; a wall at ground level is
    checked on the ground spectrum (§C8.7.1.2.1.8), which is what is returned for z/H = 0.

    Args:
        periods: element periods T ≥ 0 [s].
        ground: the elastic ground spectrum Se(T [s], ξ [-]) [g].
        period: T1 [s] of the building.
        storeys: n [-].
        z_over_h: z/H [-] of the element's base.
        building_damping: ξ1 [-] of the building's first mode.
        damping: ξ [-] of the element (5 %; 8 % SLV and 10 % SLC in §C8.7.1.2.1.8).
        a, b: ends of the plateau as fractions of T1 (0.8 and 1.1 in the text).
    """
    _check_oscillator(period, building_damping)
    if not (0.0 < a < 1.0 < b):
        raise ValueError(f"need 0 < a < 1 < b, got a = {a!r}, b = {b!r}")
    T = np.asarray(periods, dtype=float)
    if np.any(T < 0.0) or not np.all(np.isfinite(T)):
        raise ValueError("periods must be finite and >= 0")
    se = np.asarray(ground(T, damping), dtype=float)
    if z_over_h == 0.0:
        return np.array(se, dtype=float)
    se_t1 = float(np.asarray(ground(np.asarray([period]), building_damping))[0])
    a_z = floor_peak_acceleration(
        se_t1, storeys=storeys, z_over_h=z_over_h, building_damping=building_damping
    )
    amp = floor_amplification(building_damping, damping)
    top = amp * a_z
    lo, hi = a * period, b * period
    rising = top / (1.0 + (amp - 1.0) * libm.power(np.clip(1.0 - T / lo, 0.0, None), 1.6))
    falling = top / (1.0 + (amp - 1.0) * libm.power(np.clip(T / hi - 1.0, 0.0, None), 1.2))
    sez = np.where(T < lo, rising, np.where(T < hi, top, falling))
    return np.where(T > period, np.maximum(sez, se), sez)


def floor_displacement_spectrum(
    periods: ArrayLike,
    ground: GroundSpectrum,
    *,
    period: float,
    storeys: int,
    z_over_h: float,
    building_damping: float = 0.05,
    damping: float = 0.05,
    a: float = FLOOR_PLATEAU_A,
    b: float = FLOOR_PLATEAU_B,
) -> NDArray[np.float64]:
    """S_DeZ(T) = S_eZ(T)·(T/2π)²·g [m]: the floor displacement spectrum (Circolare 2019
    §C8.7.1.2.1.8), not less than S_eZ(T1)·(b·T1/2π)²·g for T > b·T1 (eq. C8.7.1.12).

    Arguments as :func:`floor_spectrum`; at z/H = 0 it is the ground's pseudo-displacement
    spectrum Se(T, ξ)·(T/2π)²·g (NTC 2018 §3.2.3.2.3, eq. 3.2.12).
    """
    T = np.asarray(periods, dtype=float)
    sez = floor_spectrum(
        T,
        ground,
        period=period,
        storeys=storeys,
        z_over_h=z_over_h,
        building_damping=building_damping,
        damping=damping,
        a=a,
        b=b,
    )
    sd = sez * G * (T / (2.0 * math.pi)) ** 2
    if z_over_h == 0.0:
        return sd
    top = floor_spectrum(
        np.asarray([period]),
        ground,
        period=period,
        storeys=storeys,
        z_over_h=z_over_h,
        building_damping=building_damping,
        damping=damping,
        a=a,
        b=b,
    )[0]
    floor_bound = top * G * (b * period / (2.0 * math.pi)) ** 2
    return np.where(T > b * period, np.maximum(sd, floor_bound), sd)


def ground_displacement_spectrum(
    periods: ArrayLike, ground: GroundSpectrum, damping: float
) -> NDArray[np.float64]:
    """S_De(T) = Se(T, ξ)·(T/2π)²·g [m], the elastic displacement spectrum at ground level
    (NTC 2018 §3.2.3.2.3, eq. 3.2.12, valid up to T_E; ξ [-], Se in g)."""
    T = np.asarray(periods, dtype=float)
    return np.asarray(ground(T, damping), dtype=float) * G * (T / (2.0 * math.pi)) ** 2
