"""The loads a wall carries, for the dynamics (docs/model.md §12; SI units, per metre of wall).

:class:`Loads` holds the vertical loads on the top of the wall (their mass carried by the
wall or not), the outward thrusts and the steel ties; :func:`side_terms` turns them into the
constants of the equation of motion on one side, in the kernel's normalisation (moments per
m·g·R of the wall, :mod:`frp_assess.dynamics.kernel.steppers`): the restoring bracket of §12

    A_s·cos θ + B_s·sin θ,   A_s = a0_s + u·a1_s,   B_s = K_s + b0_s + u·b1_s   (u = ü_g/g)

with, W·R the weight moment of the wall, u_i its lever from the pivot of side s,

    a0_s = s·sin α + (s·Σ P_i·u_i − Σ F_j·h_j)/(W·R)
    a1_s = cos α + Σ_carried P_i·H/(W·R)
    b0_s = −cos α − (Σ P_i·H + [s > 0]·Σ F_j·B)/(W·R)
    b1_s = s·sin α + s·Σ_carried P_i·u_i/(W·R)

and p²_s = W·R/I_s, I_s = I₀ + Σ_carried (P_i/g)·(u_i² + H²).  Without loads they are the
wall's own numbers, bit for bit (s·sin α, cos α, −cos α, s·sin α, p²): the same arithmetic.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

from frp_assess.dynamics.kernel.params import TieParams
from frp_assess.dynamics.wall import Wall
from frp_assess.motions.record import G
from frp_assess.rules.tie_rods import (
    MAX_TIE_LEVELS,
    TIE_LEVELS_RULE,
    tie_anchorage_force,
    tie_level_of_each,
)
from frp_assess.rules.wall_loads import Thrust, TopLoad, lever


@dataclass(frozen=True)
class Tie:
    """The steel ties at one height, per metre of wall (:mod:`frp_assess.rules.tie_rods`)."""

    height: float  #: h_t [m] above the rocking base
    stiffness: float  #: k_t = E_s·A_s/(L_t·i_t) [N/m per m]
    yield_force: float  #: F_y = A_s·f_y/i_t [N/m]
    anchorage_force: float  #: F_a/i_t [N/m]; inf when the anchorage does not govern

    @classmethod
    def of(cls, height: float, stiffness: float, yield_force: float, anchorage: float | None,
           spacing: float) -> Tie:  # fmt: skip
        """The ties at ``height`` [m] with an anchorage of ``anchorage`` [N per tie] (None:
        not governing) every ``spacing`` [m]."""
        return cls(height, stiffness, yield_force, tie_anchorage_force(anchorage, spacing))


@dataclass(frozen=True)
class Loads:
    """What bears on and pushes the wall (SI: N/m, m).  Empty: the free-standing wall."""

    top: tuple[TopLoad, ...] = ()
    thrusts: tuple[Thrust, ...] = ()
    ties: tuple[Tie, ...] = ()

    def __bool__(self) -> bool:
        return bool(self.top or self.thrusts or self.ties)

    @property
    def vertical(self) -> float:
        """Σ P_i [N/m]: the vertical loads the base carries besides the wall's weight."""
        return sum(p.force for p in self.top)

    def carried(self) -> tuple[TopLoad, ...]:
        """The top loads whose mass moves with the wall."""
        return tuple(p for p in self.top if p.carried)


NO_LOADS = Loads()


def tie_levels(loads: Loads) -> tuple[Tie, ...]:
    """The tie levels the time histories model (docs/model.md §12), in the order of the ties;
    () without a tie.

    A tie that carries nothing (k_t, F_y or F_a zero) is no tie.  Ties that act as one
    (:func:`~frp_assess.rules.tie_rods.same_tie_level`: at the same height, yielding and
    losing their anchorage at the same elongations; the usual row of equal ties, or two rows
    of the same steel and length) are summed into one level; more than MAX_TIE_LEVELS levels
    are refused with one line (the project file's check refuses them first:
    config/schema/loads_spec.py).
    """
    ties = [
        t
        for t in loads.ties
        if t.stiffness > 0.0 and t.yield_force > 0.0 and t.anchorage_force > 0.0
    ]
    of_each = tie_level_of_each([_numbers(t) for t in ties])
    count = max(of_each, default=-1) + 1
    if count > MAX_TIE_LEVELS:
        raise ValueError(f"the time histories model {TIE_LEVELS_RULE}; found {count} levels")
    levels = []
    for j in range(count):
        group = [t for t, level in zip(ties, of_each, strict=True) if level == j]
        levels.append(
            Tie(
                group[0].height,
                sum(t.stiffness for t in group),
                sum(t.yield_force for t in group),
                sum(t.anchorage_force for t in group),
            )
        )
    return tuple(levels)


def tie_params(wall: Wall, levels: tuple[Tie, ...]) -> TieParams:
    """The kernel's constants of the tie levels (:class:`~frp_assess.dynamics.kernel.params.
    TieParams`): each one's height, k_t·h_t/(W·R), the yield
    elongation F_y/k_t and the rotation where a brittle tie (F_a ≤ F_y) is lost; the entries
    beyond the wall's levels (all of them without a tie) are numbers that are never read."""
    if len(levels) > MAX_TIE_LEVELS or MAX_TIE_LEVELS != 2:
        raise ValueError(f"the kernel holds 2 tie levels, got {len(levels)}")
    height, kn, yields, losses = [1.0] * 2, [0.0] * 2, [math.inf] * 2, [math.inf] * 2
    for j, tie in enumerate(levels):
        h, k = tie.height, tie.stiffness
        height[j], kn[j], yields[j] = h, k * h / (wall.weight * wall.R), tie.yield_force / k
        if tie.anchorage_force <= tie.yield_force and tie.anchorage_force < k * h:
            losses[j] = math.asin(tie.anchorage_force / (k * h))
    return TieParams(
        len(levels), (height[0], height[1]), (kn[0], kn[1]),
        (yields[0], yields[1]), (losses[0], losses[1]),
    )  # fmt: skip


def _numbers(t: Tie) -> tuple[float, float, float, float]:
    return t.height, t.stiffness, t.yield_force, t.anchorage_force


class SideTerms(NamedTuple):
    """The constants of the equation of motion on one side (module docstring)."""

    p2: float  #: p²_s = W·R/I_s [1/s²]
    a0: float  #: [-]
    a1: float  #: [-]
    b0: float  #: [-]
    b1: float  #: [-]


def inertia(wall: Wall, loads: Loads, side: int) -> float:
    """I_s about the pivot of ``side`` [kg·m²/m]: I₀ + Σ_carried (P_i/g)·(u_i² + H²)."""
    total = wall.I0
    for p in loads.carried():
        u = lever(p, wall.thickness, side)
        total += p.force / G * (u * u + wall.height * wall.height)
    return total


def side_terms(wall: Wall, loads: Loads, side: int, sin_a: float, cos_a: float) -> SideTerms:
    """The constants of ``side`` (+1 outward, −1 inward) with ``sin_a``, ``cos_a`` the kernel's
    sin α, cos α (module docstring).  Without loads: (p², s·sin α, cos α, −cos α, s·sin α)."""
    s = float(side)
    if not (loads.top or loads.thrusts):
        return SideTerms(wall.p2, s * sin_a, cos_a, -cos_a, s * sin_a)
    wr = wall.weight * wall.R
    h = wall.height
    hold = sum(p.force * lever(p, wall.thickness, side) for p in loads.top)
    push = sum(f.force * f.height for f in loads.thrusts)
    carried_h = sum(p.force * h for p in loads.carried())
    carried_u = sum(p.force * lever(p, wall.thickness, side) for p in loads.carried())
    sink = loads.vertical * h + (sum(f.force for f in loads.thrusts) * wall.thickness if side > 0
                                 else 0.0)  # fmt: skip
    return SideTerms(
        p2=wr / inertia(wall, loads, side),
        a0=s * sin_a + (s * hold - push) / wr,
        a1=cos_a + carried_h / wr,
        b0=-cos_a - sink / wr,
        b1=s * sin_a + s * carried_u / wr,
    )
