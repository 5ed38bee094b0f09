"""Free vibration after the input: when the wall's fate is certain (docs/model.md §3, collapse).

With no ground motion the mechanical energy per unit I0 on side s,

    E = ½θ'² + V_s(θ),   V_s(θ) = p²·[cos(α − |θ|) + K_s·(1 − cos θ)],

only falls at impacts (θ = 0, where every V_s = p²·cos α), is kept by an Eq. 12 rupture and
lowered by a velocity-continuous one.  V_s rises from θ = 0 up to the tipping angle θ*_s
(tan θ* = sin α / (cos α − K_s); none below π/2 when K_s ≥ cos α; α with no bar).  On its
way out the wall meets first either θ*_s (beyond it, it falls) or θ_max of an intact bar (an
event that changes the potential).  So while the wall is inside that well (|θ| below the nearer
of the two) with E below V_s there on every side it can still reach, no event can ever happen
again: the wall cannot fall.
"""

from __future__ import annotations

import math

from numba import njit

from frp_assess.dynamics.kernel.params import KernelParams

_HALF_PI = 0.5 * math.pi


@njit(cache=True, nogil=True)
def potential(theta: float, k_s: float, prm: KernelParams) -> float:
    """V_s(θ) per unit I0 [rad²/s²]: gravity about the pivot plus the acting bar's energy."""
    return prm.p2 * (math.cos(prm.alpha - abs(theta)) + k_s * (1.0 - math.cos(theta)))


@njit(cache=True, nogil=True)
def tipping_angle(k_s: float, prm: KernelParams) -> float:
    """θ*: where V_s stops rising, tan θ* = sin α/(cos α − K_s); π/2 when K_s ≥ cos α [rad]."""
    if k_s >= prm.cos_a:
        return _HALF_PI
    return math.atan2(prm.sin_a, prm.cos_a - k_s)


@njit(cache=True, nogil=True)
def barrier_angle(bar_intact: bool, prm: KernelParams) -> float:
    """Largest |θ| the wall can reach on a side without an event: min(θ*, θ_max) [rad]."""
    if not bar_intact:
        return prm.alpha
    return min(tipping_angle(prm.k_bar, prm), prm.theta_max)


@njit(cache=True, nogil=True)
def barrier(bar_intact: bool, prm: KernelParams) -> float:
    """V_s at the barrier angle of a side [rad²/s²]: the energy that can change the wall's fate."""
    k_s = prm.k_bar if bar_intact else 0.0
    return potential(barrier_angle(bar_intact, prm), k_s, prm)


@njit(cache=True, nogil=True)
def turning_angle(energy: float, bar_intact: bool, prm: KernelParams) -> float:
    """|θ| where V_s = ``energy`` on a side whose barrier is above it [rad] (bisection)."""
    k_s = prm.k_bar if bar_intact else 0.0
    lo = 0.0
    hi = barrier_angle(bar_intact, prm)
    if potential(lo, k_s, prm) >= energy:
        return 0.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if potential(mid, k_s, prm) < energy:
            lo = mid
        else:
            hi = mid
        if hi - lo <= 1e-15:
            break
    return 0.5 * (lo + hi)


@njit(cache=True, nogil=True)
def cannot_fall(
    theta: float, omega: float, s: float, intact_pos: bool, intact_neg: bool, prm: KernelParams
) -> bool:
    """True when, with no more ground motion, the wall can never fall (nor break a bar).

    The wall must be inside the well of its side (|θ| below the barrier angle: beyond the
    tipping angle it can only fall) with less energy than every barrier it can reach.
    """
    intact_s = intact_pos if s > 0.0 else intact_neg
    if abs(theta) >= barrier_angle(intact_s, prm):
        return False
    k_s = prm.k_bar if intact_s else 0.0
    energy = 0.5 * omega * omega + potential(theta, k_s, prm)
    if energy >= barrier(intact_pos, prm):
        return False
    if not prm.one_sided and energy >= barrier(intact_neg, prm):
        return False
    return True


@njit(cache=True, nogil=True)
def remaining_peak(
    theta: float, omega: float, s: float, intact_pos: bool, intact_neg: bool, prm: KernelParams
) -> tuple[float, bool]:
    """Largest |θ| still to come once :func:`cannot_fall` holds, and whether a bar acts there.

    Moving outward, the wall turns where V_s = E; moving inward, it first strikes (θ = 0,
    kinetic energy × e²) and turns on the side it then rocks on.  Later excursions only have
    less energy.
    """
    intact_s = intact_pos if s > 0.0 else intact_neg
    k_s = prm.k_bar if intact_s else 0.0
    energy = 0.5 * omega * omega + potential(theta, k_s, prm)
    if s * omega > 0.0:
        return turning_angle(energy, intact_s, prm), intact_s
    v0 = potential(0.0, 0.0, prm)
    after = v0 + prm.e_impact * prm.e_impact * (energy - v0)
    s_next = s if prm.one_sided else -s
    intact_next = intact_pos if s_next > 0.0 else intact_neg
    return turning_angle(after, intact_next, prm), intact_next
