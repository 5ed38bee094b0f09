"""Simple overturning of a façade with the loads it carries (SI: m, N, kg; per metre of wall).

The Circolare's kinematic analysis of simple overturning (Circolare 2019 §C8.7.1.2, eq.
C8.7.1.1) takes every weight, load, thrust and tie acting on the rotating block; this module
holds its formulas, written once, for the dynamics, the code checks and the report
(docs/model.md §12).  Frame: the outer face is the one the façade falls away from; a
rotation θ > 0 turns the wall outward about the outer base corner O, θ < 0 (two-sided
mechanisms only) inward about the inner corner O′.  A point at distance u from the pivot
corner (along the base, into the wall) and height y has, at rotation |θ|,

* the horizontal lever X = u·cos θ − y·sin|θ| (the arm of a vertical force), and
* the height Y = u·sin|θ| + y·cos θ above the pivot (the arm of a horizontal force).

Loads: a vertical load P_i on the top of the wall at d_i from the outer face (its lever
u_i = d_i about O, B − d_i about O′), whose mass P_i/g moves with the wall when it is
*carried* and is held by other walls when *restrained*; a thrust F_j pushing outward on the
inner face at height h_j; a tie at height h_t on the outer face (tension only, outward
rotations only: :mod:`frp_assess.rules.tie_rods`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import NamedTuple


class TopLoad(NamedTuple):
    """A vertical load on the top of the wall (a floor, the roof)."""

    force: float  #: P [N/m], downward
    distance: float  #: d [m] of its line of action from the outer face, 0 <= d <= B
    carried: bool  #: whether its mass P/g moves horizontally with the top of the wall


class Thrust(NamedTuple):
    """A horizontal force pushing the wall outward on its inner face (a roof, a vault)."""

    force: float  #: F [N/m]
    height: float  #: h [m] above the base


def lever(load: TopLoad, thickness: float, side: int) -> float:
    """u [m]: the distance of a top load's line of action from the pivot of ``side``
    (+1: the outer corner, u = d; −1: the inner corner, u = B − d; docs/model.md §12)."""
    return load.distance if side > 0 else thickness - load.distance


def stabilising_moment(
    weight: float,
    thickness: float,
    height: float,
    top: Sequence[TopLoad],
    thrusts: Sequence[Thrust],
    side: int,
    base_moment: float = 0.0,
) -> float:
    """Σ of the moments about the pivot of ``side`` that hold the wall at θ = 0 [N·m/m]:
    W·B/2 + Σ P_i·u_i − base_moment ∓ Σ F_j·h_j (the thrusts overturn outward, hold inward).

    ``base_moment`` is N₀·x₀/2, the moment lost when the pivot moves into the wall by half the
    compressed zone x₀ (docs/model.md §10; 0 with the edge pivot).
    """
    moment = weight * thickness / 2.0 + sum(p.force * lever(p, thickness, side) for p in top)
    push = sum(f.force * f.height for f in thrusts)
    return moment - base_moment - push if side > 0 else moment - base_moment + push


def overturning_moment_per_g(weight: float, height: float, top: Sequence[TopLoad]) -> float:
    """Σ of the weights' moments of the horizontal inertia at θ = 0 per unit of acceleration
    in g [N·m/m]: W·H/2 + Σ_carried P_i·H (Circolare 2019 eq. C8.7.1.1, Σ (P + Q)·δ_PQx with
    a unit virtual rotation; restrained loads bring no horizontal force)."""
    return weight * height / 2.0 + sum(p.force * height for p in top if p.carried)


def uplift_multiplier(
    weight: float,
    thickness: float,
    height: float,
    top: Sequence[TopLoad],
    thrusts: Sequence[Thrust],
    side: int,
    base_moment: float = 0.0,
) -> float:
    """α_s = a_RM,s/g [-], the ground acceleration (in g) that starts rocking on ``side``
    (docs/model.md §12):

        a_RM,+ = g·(W·B/2 + Σ P_i·d_i − N₀·x₀/2 − Σ F_j·h_j) / (W·H/2 + Σ_carried P_i·H)
        a_RM,− = g·(W·B/2 + Σ P_i·(B − d_i) − N₀·x₀/2 + Σ F_j·h_j) / (W·H/2 + Σ_carried P_i·H)

    For the outward side this is the Circolare's α₀ of simple overturning (eq. C8.7.1.1)
    without a tie.  ≤ 0: the thrusts tip the wall without an earthquake.
    """
    return stabilising_moment(
        weight, thickness, height, top, thrusts, side, base_moment
    ) / overturning_moment_per_g(weight, height, top)


def overturning_multiplier(
    weight: float,
    thickness: float,
    height: float,
    top: Sequence[TopLoad],
    thrusts: Sequence[Thrust],
    tie_moment: float = 0.0,
    base_moment: float = 0.0,
) -> float:
    """α₀ [-] of simple overturning (Circolare 2019 eq. C8.7.1.1, linear kinematic analysis):

        α₀ = [Σ P_k·δ_Py − Σ F_k·δ_F + L_i] / Σ (P_k + Q_k)·δ_PQx

    with a virtual outward rotation about the outer base corner: the weight and the top loads
    hold (W·B/2 + Σ P_i·d_i), the thrusts overturn (Σ F_j·h_j), and a tie at its capacity
    does the internal work L_i = min(F_y, F_a)·h_t (``tie_moment``, summed over the ties),
    as the Circolare's rigid-plastic analysis counts it.
    """
    return (
        stabilising_moment(weight, thickness, height, top, thrusts, 1, base_moment) + tie_moment
    ) / overturning_moment_per_g(weight, height, top)


def multiplier_at_rotation(
    theta: float,
    weight: float,
    thickness: float,
    height: float,
    top: Sequence[TopLoad],
    thrusts: Sequence[Thrust],
    tie_moment: float = 0.0,
) -> float:
    """α(θ) [-] of the capacity curve of simple overturning (Circolare 2019 §C8.7.1.2.1) at an
    outward rotation θ ≥ 0 about the outer corner: the ratio of the moments that hold the wall
    to those of the horizontal inertia per g, in the turned geometry (docs/model.md §12).

    ``tie_moment`` is the ties' moment F_t(θ)·h_t·cos θ at that rotation (the caller knows the
    force from :func:`frp_assess.rules.tie_rods.tie_force`).  The edge pivot.
    """
    c = math.cos(theta)
    s = math.sin(theta)
    hold = weight * (thickness / 2.0 * c - height / 2.0 * s)
    hold += sum(p.force * (p.distance * c - height * s) for p in top)
    hold -= sum(f.force * (f.height * c + thickness * s) for f in thrusts)
    hold += tie_moment
    drive = weight * (height / 2.0 * c + thickness / 2.0 * s)
    drive += sum(p.force * (height * c + p.distance * s) for p in top if p.carried)
    return hold / drive


def participating_mass_ratio(weight: float, height: float, top: Sequence[TopLoad]) -> float:
    """e* [-] of the wall and the carried loads (Circolare 2019 eq. C8.7.1.5, the virtual
    horizontal displacements of a rotation about the base: H/2 for the wall's weight at its
    centroid, H for the loads on its top):

        e* = (W·H/2 + Σ P_c·H)² / ((W + Σ P_c)·(W·H²/4 + Σ P_c·H²))

    1 for the wall alone (one block, its weight at the centroid).
    """
    carried = [p.force for p in top if p.carried]
    moment = weight * height / 2.0 + sum(carried) * height
    return (
        moment
        * moment
        / ((weight + sum(carried)) * (weight * height * height / 4.0 + sum(carried) * height**2))
    )


def participating_weight(weight: float, top: Sequence[TopLoad]) -> float:
    """W + Σ P_c [N/m]: the weights whose horizontal inertia the mechanism carries (M*·g/e*,
    Circolare 2019 eq. C8.7.1.5)."""
    return weight + sum(p.force for p in top if p.carried)


def impact_velocity_ratio(
    mass: float,
    thickness: float,
    height: float,
    carried: Sequence[tuple[float, float]],
    new_side: int,
) -> float:
    """e_c [-]: the ratio of the angular velocity after an impact to that before it, when the
    pivot moves to the corner of ``new_side`` (+1 outer, −1 inner), from the conservation of
    angular momentum about the new corner (Housner 1963, with point masses on the top;
    docs/model.md §12):

        e_c = [m·R²/3 + m·(h² − b²) + Σ m_i·(H² − d_i·(B − d_i))] / I_new

    h = H/2, b = B/2, R² = b² + h², I_new = (4/3)·m·R² + Σ m_i·(u_i² + H²) about the new
    corner (u_i = d_i outer, B − d_i inner).  ``carried`` holds (m_i [kg/m], d_i [m]) of the
    carried loads.  Without loads: 1 − 1.5·sin²α.
    """
    b = thickness / 2.0
    h = height / 2.0
    r2 = b * b + h * h
    before = mass * r2 / 3.0 + mass * (h * h - b * b)
    inertia = 4.0 / 3.0 * mass * r2
    for m_i, d_i in carried:
        before += m_i * (height * height - d_i * (thickness - d_i))
        u_i = d_i if new_side > 0 else thickness - d_i
        inertia += m_i * (u_i * u_i + height * height)
    return before / inertia
