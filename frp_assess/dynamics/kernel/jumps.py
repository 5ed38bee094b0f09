"""The jumps of the state at the events of Eq. 10 (docs/model.md §3.2–3.4): uplift from rest,
impact at θ = 0, rupture of a bar at θ_max."""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from frp_assess.dynamics.kernel.params import (
    BAR_SHARED,
    REST_VELOCITY,
    RUPTURE_ENERGY_TRANSFER,
    KernelParams,
)

#: Relative margin of the tests that a wall at rest cannot uplift in a sample interval: the
#: interval is taken as quiet only when both its samples are below the threshold by more
#: than this, so rounding in :func:`uplift` (ü at the interval's end is rebuilt from its
#: slope) can never matter.
QUIET_MARGIN = 1e-9


@njit(cache=True, nogil=True)
def rest_until(acc: np.ndarray, i: int, last: int, bound: float) -> int:
    """The first sample interval k in [i, last] that may uplift a wall at rest: every
    interval before it has both its samples below ``bound`` [m/s²] in absolute value (the
    record ``acc`` [m/s²], zero beyond its end), so :func:`uplift` would find nothing in it.
    ``bound`` = (1 − QUIET_MARGIN)·g·tan α_x / C for the multiplier C."""
    n_rec = acc.shape[0]
    k = i
    while k < last:
        a0 = abs(acc[k]) if k < n_rec else 0.0
        a1 = abs(acc[k + 1]) if k + 1 < n_rec else 0.0
        if a0 >= bound or a1 >= bound:
            break
        k += 1
    return k


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
