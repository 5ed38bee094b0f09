"""Free vibration after the input: when the wall's fate is certain (docs/model.md §3, collapse).

With no ground motion the mechanical energy per unit I0 on side s,

    E = ½θ'² + V_s(θ),
    V_s(θ) = p²·[cos(α − |θ|) + K_s·(1 − cos θ) − ξ·∫₀^|θ| n_s(φ)²·cos φ dφ],

(the last term is the base reaction, n_s = 1 + κ_s·sin(φ/2); docs/model.md §1.1) only falls at
impacts (θ = 0, where every V_s = p²·cos α), and jumps at a rupture by Eq. 12's U_r and by the
bar's share of the reaction term (both are recomputed from the new bar state).  V_s rises from
θ = 0 up to the tipping angle θ*_s (the first zero of the restoring moment; with the edge pivot
tan θ* = sin α / (cos α − K_s), none below π/2 when K_s ≥ cos α; α_x with no bar).  On its way
out the wall meets first either θ*_s (beyond it, it falls), θ_max of an intact bar (an event
that changes the potential) or θ_cr of an intact bar (the toe crushes: a failure).  So while the
wall is inside that well (|θ| below the nearest of the three) with E below V_s there on every
side it can still reach, no event can ever happen again: the wall cannot fall.
"""

from __future__ import annotations

import math

from numba import njit

from frp_assess.dynamics.kernel.params import KernelParams

_HALF_PI = 0.5 * math.pi
#: Grid on [0, π/2] on which the first zero of the restoring moment is bracketed.
_TIP_GRID = 256


@njit(cache=True, nogil=True)
def reaction_integral(t: float, kappa: float) -> float:
    """∫₀^t n(φ)²·cos φ dφ, n = 1 + κ·sin(φ/2), t ≥ 0 [-] (closed form: with c = cos(t/2),
    ∫ sin(φ/2)·cos φ = 2c − 4c³/3 − 2/3 and ∫ sin²(φ/2)·cos φ = ½ sin t − t/4 − sin 2t/8)."""
    st = math.sin(t)
    c = math.cos(0.5 * t)
    linear = 2.0 * c - (4.0 / 3.0) * c * c * c - 2.0 / 3.0
    square = 0.5 * st - 0.25 * t - 0.25 * st * math.cos(t)
    return st + 2.0 * kappa * linear + kappa * kappa * square


@njit(cache=True, nogil=True)
def potential(theta: float, k_s: float, prm: KernelParams) -> float:
    """V_s(θ) per unit I0 [rad²/s²]: gravity about the corner, the acting bar's energy and
    the base reaction."""
    v = math.cos(prm.alpha - abs(theta)) + k_s * (1.0 - math.cos(theta))
    if prm.xi != 0.0:
        v -= prm.xi * reaction_integral(abs(theta), k_s * prm.kappa_per_k)
    return prm.p2 * v


@njit(cache=True, nogil=True)
def restoring(theta: float, k_s: float, prm: KernelParams) -> float:
    """The restoring moment per m·g·R at θ ≥ 0 [-]: sin(α − θ) + K_s·sin θ − ξ·n²·cos θ."""
    m = math.sin(prm.alpha - theta) + k_s * math.sin(theta)
    if prm.xi != 0.0:
        n = 1.0 + k_s * prm.kappa_per_k * math.sin(0.5 * theta)
        m -= prm.xi * n * n * math.cos(theta)
    return m


@njit(cache=True, nogil=True)
def tipping_angle(k_s: float, prm: KernelParams) -> float:
    """θ*: where V_s stops rising, the first zero of :func:`restoring` in (0, π/2] [rad].

    Edge pivot: tan θ* = sin α/(cos α − K_s), π/2 when K_s ≥ cos α.  With the base reaction:
    α_x with no bar, else bracketed on a grid and bisected (π/2 when it stays positive).
    """
    if prm.xi == 0.0:
        if k_s >= prm.cos_a:
            return _HALF_PI
        return math.atan2(prm.sin_a, prm.cos_a - k_s)
    if k_s == 0.0:
        return prm.alpha_x
    return first_zero(1.0, k_s, prm)


@njit(cache=True, nogil=True)
def _restoring_of(q: float, side: float, k_s: float, prm: KernelParams) -> float:
    """The static restoring moment of ``side`` at |θ| = q: :func:`restoring` for the wall
    alone, :func:`loaded_restoring` with loads."""
    if prm.loaded:
        return loaded_restoring(q, side, k_s, prm)
    return restoring(q, k_s, prm)


@njit(cache=True, nogil=True)
def first_zero(side: float, k_s: float, prm: KernelParams) -> float:
    """The first zero of the side's static restoring moment in (0, π/2] [rad]: bracketed on a
    grid and bisected; π/2 when it stays positive."""
    lo = 0.0
    for i in range(1, _TIP_GRID + 1):
        hi = _HALF_PI * i / _TIP_GRID
        if _restoring_of(hi, side, k_s, prm) <= 0.0:
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                if _restoring_of(mid, side, k_s, prm) > 0.0:
                    lo = mid
                else:
                    hi = mid
                if hi - lo <= 1e-15:
                    break
            return 0.5 * (lo + hi)
        lo = hi
    return _HALF_PI


@njit(cache=True, nogil=True)
def barrier_angle(bar_intact: bool, prm: KernelParams) -> float:
    """Largest |θ| the wall can reach on a side without an event: min(θ*, θ_max, θ_cr) [rad]."""
    if not bar_intact:
        return prm.alpha_x
    return min(prm.tip_bar, prm.theta_max, prm.theta_cr)


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
    if prm.loaded:
        return loaded_cannot_fall(theta, omega, s, intact_pos, intact_neg, prm)
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
    if prm.loaded:
        return loaded_remaining_peak(theta, omega, s, intact_pos, intact_neg, prm)
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


# --- with the loads of docs/model.md §12 -----------------------------------------------------
# The sides differ (levers, thrusts, inertia), so each quantity takes its side, and energies
# are compared across sides in one unit, the energy over the wall's weight moment W·R:
#     ε = ½·θ'²/p²_s + v_s(|θ|),   v_s(q) = cos α + s·a0_s·sin q + (K_s + b0_s)·(1 − cos q)
#                                            − ξ·∫₀^q n²·cos φ dφ,
# the integral of the side's static restoring moment s·a0_s·cos q + (K_s + b0_s)·sin q − ξ·n²·cos q
# (v_s(0) = cos α on both sides; without loads v_s = V/p² of the functions above).


@njit(cache=True, nogil=True)
def side_p2(side: float, prm: KernelParams) -> float:
    """p²_s [1/s²] of the side."""
    return prm.p2_pos if side > 0.0 else prm.p2_neg


@njit(cache=True, nogil=True)
def loaded_potential(q: float, side: float, k_s: float, prm: KernelParams) -> float:
    """v_s(q) [-]: the potential energy over W·R at |θ| = q on ``side`` (module comment)."""
    a0 = prm.a0_pos if side > 0.0 else prm.a0_neg
    b0 = prm.b0_pos if side > 0.0 else prm.b0_neg
    v = prm.cos_a + side * a0 * math.sin(q) + (k_s + b0) * (1.0 - math.cos(q))
    if prm.xi != 0.0:
        v -= prm.xi * reaction_integral(q, k_s * prm.kappa_per_k)
    return v


@njit(cache=True, nogil=True)
def loaded_restoring(q: float, side: float, k_s: float, prm: KernelParams) -> float:
    """The static restoring moment over W·R at |θ| = q ≥ 0 on ``side`` [-] (dv_s/dq)."""
    a0 = prm.a0_pos if side > 0.0 else prm.a0_neg
    b0 = prm.b0_pos if side > 0.0 else prm.b0_neg
    m = side * a0 * math.cos(q) + (k_s + b0) * math.sin(q)
    if prm.xi != 0.0:
        n = 1.0 + k_s * prm.kappa_per_k * math.sin(0.5 * q)
        m -= prm.xi * n * n * math.cos(q)
    return m


@njit(cache=True, nogil=True)
def loaded_tipping_angle(side: float, k_s: float, prm: KernelParams) -> float:
    """θ*_s: the first zero of :func:`loaded_restoring` in (0, π/2] [rad] (π/2: none)."""
    return first_zero(side, k_s, prm)


@njit(cache=True, nogil=True)
def loaded_barrier_angle(side: float, bar_intact: bool, prm: KernelParams) -> float:
    """min(θ*_s, θ_max, θ_cr) with the bar intact, α_x of the side without [rad]."""
    if not bar_intact:
        return prm.alpha_x if side > 0.0 else prm.alpha_x_neg
    tip = prm.tip_bar if side > 0.0 else prm.tip_bar_neg
    return min(tip, prm.theta_max, prm.theta_cr)


@njit(cache=True, nogil=True)
def loaded_barrier(side: float, bar_intact: bool, prm: KernelParams) -> float:
    """v_s at the side's barrier angle [-]."""
    k_s = prm.k_bar if bar_intact else 0.0
    return loaded_potential(loaded_barrier_angle(side, bar_intact, prm), side, k_s, prm)


@njit(cache=True, nogil=True)
def loaded_turning_angle(energy: float, side: float, bar_intact: bool, prm: KernelParams) -> float:
    """|θ| where v_s = ``energy`` [-] below the side's barrier [rad] (bisection)."""
    k_s = prm.k_bar if bar_intact else 0.0
    lo = 0.0
    hi = loaded_barrier_angle(side, bar_intact, prm)
    if loaded_potential(lo, side, k_s, prm) >= energy:
        return 0.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if loaded_potential(mid, side, k_s, prm) < energy:
            lo = mid
        else:
            hi = mid
        if hi - lo <= 1e-15:
            break
    return 0.5 * (lo + hi)


@njit(cache=True, nogil=True)
def loaded_energy(theta: float, omega: float, s: float, k_s: float, prm: KernelParams) -> float:
    """ε = ½·θ'²/p²_s + v_s(|θ|) [-] (module comment)."""
    return 0.5 * omega * omega / side_p2(s, prm) + loaded_potential(abs(theta), s, k_s, prm)


@njit(cache=True, nogil=True)
def loaded_cannot_fall(
    theta: float, omega: float, s: float, intact_pos: bool, intact_neg: bool, prm: KernelParams
) -> bool:
    """:func:`cannot_fall` with the loads: every barrier the wall can reach, in ε."""
    intact_s = intact_pos if s > 0.0 else intact_neg
    if abs(theta) >= loaded_barrier_angle(s, intact_s, prm):
        return False
    energy = loaded_energy(theta, omega, s, prm.k_bar if intact_s else 0.0, prm)
    if energy >= loaded_barrier(1.0, intact_pos, prm):
        return False
    if not prm.one_sided and energy >= loaded_barrier(-1.0, intact_neg, prm):
        return False
    return True


@njit(cache=True, nogil=True)
def loaded_remaining_peak(
    theta: float, omega: float, s: float, intact_pos: bool, intact_neg: bool, prm: KernelParams
) -> tuple[float, bool]:
    """:func:`remaining_peak` with the loads: the impact's velocity ratio of the side the
    wall then rocks on, and the kinetic energy carried over in ε."""
    intact_s = intact_pos if s > 0.0 else intact_neg
    energy = loaded_energy(theta, omega, s, prm.k_bar if intact_s else 0.0, prm)
    if s * omega > 0.0:
        return loaded_turning_angle(energy, s, intact_s, prm), intact_s
    s_next = s if prm.one_sided else -s
    e = prm.e_to_pos if s_next > 0.0 else prm.e_to_neg
    v0 = prm.cos_a
    after = v0 + e * e * (energy - v0) * side_p2(s, prm) / side_p2(s_next, prm)
    intact_next = intact_pos if s_next > 0.0 else intact_neg
    return loaded_turning_angle(after, s_next, intact_next, prm), intact_next
