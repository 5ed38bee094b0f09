"""The jumps of the state at the events of Eq. 10 (docs/model.md §3.2–3.4): uplift from rest,
impact at θ = 0, rupture of a bar at θ_max."""

from __future__ import annotations

import math

from numba import njit

from frp_assess.dynamics.kernel.params import (
    BAR_SHARED,
    REST_VELOCITY,
    RUPTURE_ENERGY_TRANSFER,
    KernelParams,
)


@njit(cache=True, nogil=True)
def uplift(
    ua: float, slope: float, x: float, x_end: float, prm: KernelParams
) -> tuple[float, float]:
    """From rest at x, the instant in [x, x_end) the wall uplifts, and its side (0: none).

    It starts with s = +1 when ü_g/g < −tan α_x and (two-sided only) with s = −1 when
    ü_g/g > tan α_x; the input is linear, so the instant is exact.
    """
    tan_a = prm.tan_ax
    ux = ua + slope * x
    ue = ua + slope * x_end
    if ux < -tan_a:
        return x, 1.0
    if (not prm.one_sided) and ux > tan_a:
        return x, -1.0
    if ue < -tan_a:
        return x + (-tan_a - ux) / slope, 1.0
    if (not prm.one_sided) and ue > tan_a:
        return x + (tan_a - ux) / slope, -1.0
    return x_end, 0.0


@njit(cache=True, nogil=True)
def impact(omega: float, s: float, prm: KernelParams) -> tuple[float, float, bool]:
    """Jump at θ = 0: (θ'₊, new s, at rest).  Two-sided: the pivot changes; one-sided: rebound."""
    if prm.one_sided:
        omega_new = -prm.e_impact * omega
        s_new = s
    else:
        omega_new = prm.e_impact * omega
        s_new = -s
    if abs(omega_new) < REST_VELOCITY * prm.p:
        return 0.0, s_new, True
    return omega_new, s_new, False


@njit(cache=True, nogil=True)
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
        omega = math.copysign(math.sqrt(omega * omega + 2.0 * prm.rupture_energy), omega)
    return omega, intact_pos, intact_neg
