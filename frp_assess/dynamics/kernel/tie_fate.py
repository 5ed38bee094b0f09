"""Free vibration of a wall held by a tie: when its fate is certain (docs/model.md §12).

The energies are those of :mod:`.fate` with the loads, in the unit W·R, plus the tie's.  On
side + a tie at h_t with plastic elongation δ_p stores ½·k_t·(δ − δ_p)² while elastic
(δ = h_t·sin θ); beyond the yield elongation it takes F_y·Δδ_p and gives none of it back.
Moving outward from its current state the wall therefore meets the *effective* potential

    w(q) = v_+(q) + τ(q),   τ = ½·k·e² for e = δ(q) − δ_p ≤ F_y/k_t,
                             ½·k·(F_y/k_t)² + k·(F_y/k_t)·(e − F_y/k_t) beyond   (k = k_t/(W·R)),

τ = 0 while e ≤ 0 (slack), and it turns where w = ε, its energy ½·θ'²/p²_s + v_s + the tie's
elastic energy.  The tipping angle of the outputs excludes the tie (docs/model.md §12: α_x of
the loads alone); the fate does not: a wall held by its tie beyond that angle cannot fall as
long as w rises above ε before π/2.  With several tie levels (:mod:`.state`) τ and the elastic
energy are the sums over the levels still anchored, and the search outward stops at the first
brittle loss among them.

**Why the test below is exact.**  ε never grows (impacts lose energy, yielding dissipates
F_y·Δδ_p, a lost tie takes its elastic energy with it).  If w(q) > ε at some q ahead, the wall
cannot pass q on this excursion; a yield on the way (before q) lowers ε and w beyond the turning
point by the same F_y·Δδ_p, so w(q) > ε still holds on every later excursion, which yields
only there.  Inward, the tie only holds: v_s alone bounds the future potential from below.
So the wall can never fall (nor reach the loss of a brittle tie, or the rupture or crushing
level of an intact bar: the cap of the search) when w(q) > ε for some q between |θ| and the
cap, and it cannot cross to side − (v_+(q) > ε for some q in [0, |θ|)) or side − is safe as
in :func:`.fate.loaded_cannot_fall`.  The searches are on a grid refined around its largest
value: a miss only postpones the verdict (the wall's energy keeps falling or the next call
finds it), never makes it wrong.
"""

from __future__ import annotations

import math

from numba import njit

from frp_assess.dynamics.kernel.fate import (
    loaded_barrier,
    loaded_barrier_angle,
    loaded_cannot_fall,
    loaded_potential,
    loaded_remaining_peak,
    loaded_turning_angle,
    side_p2,
)
from frp_assess.dynamics.kernel.params import TIE_LOST, KernelParams, TieParams
from frp_assess.dynamics.kernel.state import Regime, plastic_elongations, ties_left

#: The plastic elongations of the tie levels [m] (:func:`.state.plastic_elongations`).
Elongations = tuple[float, float]

_HALF_PI = 0.5 * math.pi
#: Points of the grid on which the effective potential is searched.
_GRID = 128
#: Golden-section iterations around the grid's largest value.
_REFINE = 40
_INV_PHI = 0.5 * (math.sqrt(5.0) - 1.0)


@njit(cache=True, nogil=True)
def tie_work(q: float, dps: Elongations, r: Regime, ties: TieParams) -> float:
    """τ(q) over W·R [-]: the work the ties still anchored take as the wall turns outward to q
    from slack, with plastic elongations δ_p = ``dps`` by level (module docstring)."""
    work = 0.0
    for j in range(ties.levels):
        if r.tie[j] == TIE_LOST:
            continue
        e = ties.height[j] * math.sin(q) - dps[j]
        if e <= 0.0:
            continue
        k = ties.kn[j] / ties.height[j]  # k_t/(W·R) [1/m²]
        fy = ties.yield_elongation[j]
        work += 0.5 * k * e * e if e <= fy else k * fy * (e - 0.5 * fy)
    return work


@njit(cache=True, nogil=True)
def tie_elastic_energy(theta: float, dps: Elongations, r: Regime, ties: TieParams) -> float:
    """The ties' elastic energy over W·R at θ [-]: Σ ½·k_t·(δ − δ_p)² of the levels still
    anchored, for 0 < δ − δ_p ≤ F_y/k_t."""
    energy = 0.0
    if theta <= 0.0:
        return energy
    for j in range(ties.levels):
        if r.tie[j] == TIE_LOST:
            continue
        e = min(ties.height[j] * math.sin(theta) - dps[j], ties.yield_elongation[j])
        if e > 0.0:
            energy += 0.5 * ties.kn[j] / ties.height[j] * e * e
    return energy


@njit(cache=True, nogil=True)
def effective_potential(
    q: float, dps: Elongations, r: Regime, k_s: float, prm: KernelParams, ties: TieParams
) -> float:
    """w(q) on side + [-]: v_+(q) and the ties' work (module docstring)."""
    return loaded_potential(q, 1.0, k_s, prm) + tie_work(q, dps, r, ties)


@njit(cache=True, nogil=True)
def tied_energy(theta: float, omega: float, r: Regime, prm: KernelParams, ties: TieParams) -> float:
    """ε with the ties' elastic energy [-]: ½·θ'²/p²_s + v_s(|θ|) + Σ ½·k_t·(δ − δ_p)²/(W·R)."""
    k_s = prm.k_bar if (r.intact_pos if r.s > 0.0 else r.intact_neg) else 0.0
    energy = 0.5 * omega * omega / side_p2(r.s, prm) + loaded_potential(abs(theta), r.s, k_s, prm)
    if r.s > 0.0:
        energy += tie_elastic_energy(theta, plastic_elongations(theta, r, ties), r, ties)
    return energy


@njit(cache=True, nogil=True)
def _outward_cap(intact_pos: bool, r: Regime, prm: KernelParams, ties: TieParams) -> float:
    """The largest q the search outward on side + covers: π/2, the loss of a brittle tie still
    anchored, the rupture and crushing levels of an intact bar (events that change the
    potential)."""
    cap = _HALF_PI
    for j in range(ties.levels):
        if r.tie[j] != TIE_LOST:
            cap = min(cap, ties.theta_loss[j])
    if intact_pos:
        cap = min(cap, prm.theta_max, prm.theta_cr)
    return cap


@njit(cache=True, nogil=True, inline="always")
def _potential(
    q: float,
    dps: Elongations,
    r: Regime,
    k_s: float,
    tied: bool,
    prm: KernelParams,
    ties: TieParams,
) -> float:
    """w(q) with ``tied``, else v_+(q) [-]."""
    if tied:
        return effective_potential(q, dps, r, k_s, prm, ties)
    return loaded_potential(q, 1.0, k_s, prm)


@njit(cache=True, nogil=True)
def _rises_above(
    energy: float,
    lo: float,
    hi: float,
    dps: Elongations,
    r: Regime,
    k_s: float,
    tied: bool,
    prm: KernelParams,
    ties: TieParams,
) -> bool:
    """Whether the potential of side + (w with ``tied``, else v_+) exceeds ``energy`` somewhere
    in [lo, hi]: a grid, then a golden-section search around its largest value."""
    if not hi > lo:
        return False
    best = -math.inf
    i_best = 0
    for i in range(_GRID + 1):
        q = lo + (hi - lo) * i / _GRID
        v = _potential(q, dps, r, k_s, tied, prm, ties)
        if v > energy:
            return True
        if v > best:
            best, i_best = v, i
    a = lo + (hi - lo) * max(i_best - 1, 0) / _GRID
    b = lo + (hi - lo) * min(i_best + 1, _GRID) / _GRID
    for _ in range(_REFINE):
        c = b - _INV_PHI * (b - a)
        d = a + _INV_PHI * (b - a)
        vc = _potential(c, dps, r, k_s, tied, prm, ties)
        vd = _potential(d, dps, r, k_s, tied, prm, ties)
        if vc > energy or vd > energy:
            return True
        if vc > vd:
            b = d
        else:
            a = c
    return False


@njit(cache=True, nogil=True)
def tied_cannot_fall(
    theta: float, omega: float, r: Regime, prm: KernelParams, ties: TieParams
) -> bool:
    """:func:`.fate.loaded_cannot_fall` with the ties (module docstring); every tie lost:
    without."""
    if not ties_left(r, ties):
        return loaded_cannot_fall(theta, omega, r.s, r.intact_pos, r.intact_neg, prm)
    energy = tied_energy(theta, omega, r, prm, ties)
    k_pos = prm.k_bar if r.intact_pos else 0.0
    q = abs(theta)
    cap = _outward_cap(r.intact_pos, r, prm, ties)
    if r.s > 0.0:
        dps = plastic_elongations(theta, r, ties)
        if not _rises_above(energy, q, cap, dps, r, k_pos, True, prm, ties):
            return False
        if prm.one_sided or _rises_above(energy, 0.0, q, dps, r, k_pos, False, prm, ties):
            return True  # it never leaves side +
    elif not _rises_above(energy, 0.0, cap, r.tie_dp, r, k_pos, True, prm, ties):
        return False  # side −: it may come back to side + and fall there
    if q >= loaded_barrier_angle(-1.0, r.intact_neg, prm) and r.s < 0.0:
        return False
    return energy < loaded_barrier(-1.0, r.intact_neg, prm)


@njit(cache=True, nogil=True)
def _first_above(
    energy: float,
    lo: float,
    dps: Elongations,
    r: Regime,
    intact_pos: bool,
    prm: KernelParams,
    ties: TieParams,
) -> float:
    """The first q ≥ lo on side + where w(q) reaches ``energy`` [rad] (the turning angle of
    the wall moving outward; the grid's bracket bisected), the cap when none."""
    k_s = prm.k_bar if intact_pos else 0.0
    hi = _outward_cap(intact_pos, r, prm, ties)
    prev = lo
    for i in range(1, _GRID + 1):
        q = lo + (hi - lo) * i / _GRID
        if effective_potential(q, dps, r, k_s, prm, ties) >= energy:
            a, b = prev, q
            for _ in range(200):
                mid = 0.5 * (a + b)
                if effective_potential(mid, dps, r, k_s, prm, ties) < energy:
                    a = mid
                else:
                    b = mid
                if b - a <= 1e-15:
                    break
            return 0.5 * (a + b)
        prev = q
    return hi


@njit(cache=True, nogil=True)
def tied_remaining_peak(
    theta: float, omega: float, r: Regime, prm: KernelParams, ties: TieParams
) -> tuple[float, bool]:
    """:func:`.fate.loaded_remaining_peak` with the ties, once :func:`tied_cannot_fall` holds:
    the largest |θ| still to come and whether the acting bar is intact there."""
    if not ties_left(r, ties):
        return loaded_remaining_peak(theta, omega, r.s, r.intact_pos, r.intact_neg, prm)
    energy = tied_energy(theta, omega, r, prm, ties)
    k_pos = prm.k_bar if r.intact_pos else 0.0
    q = abs(theta)
    if r.s > 0.0:
        dps = plastic_elongations(theta, r, ties)
        # outward it turns where w = ε; inward, held by the weights, it comes back there
        if (
            omega > 0.0
            or prm.one_sided
            or _rises_above(energy, 0.0, q, dps, r, k_pos, False, prm, ties)
        ):
            return _first_above(energy, q, dps, r, r.intact_pos, prm, ties), r.intact_pos
        after = prm.cos_a + prm.e_to_neg**2 * (energy - prm.cos_a) * prm.p2_pos / prm.p2_neg
        return loaded_turning_angle(after, -1.0, r.intact_neg, prm), r.intact_neg
    if omega < 0.0:
        return loaded_turning_angle(energy, -1.0, r.intact_neg, prm), r.intact_neg
    after = prm.cos_a + prm.e_to_pos**2 * (energy - prm.cos_a) * prm.p2_neg / prm.p2_pos
    return _first_above(after, 0.0, r.tie_dp, r, r.intact_pos, prm, ties), r.intact_pos
