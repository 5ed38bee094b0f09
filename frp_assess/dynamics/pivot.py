"""Where the wall pivots: at its compressed edge, or inside a crushed zone (docs/model.md §1.1).

Everything is per metre of wall length, in SI units (m, N, Pa, kg, s, rad).

``edge`` (the paper): the block turns about the corner of its base.  ``crushing``: the base
carries the largest compression of the model, N = W + T_u (weight of the wall and the force of
the acting bar at its design rupture strain ε_max = c·ε_u; N = W unreinforced), on a stress
block of 0.85·f_d over a depth x = N / (0.85·f_d); the resultant, and so the pivot, sits at x/2
from the compressed edge.  The depth is held for the whole time history (exact for the
unreinforced wall, a conservative constant shift with bars, whose force is below T_u until
rupture).  Every lever arm measured from the edge shrinks by x/2:

* gravity: the centre of mass is at (B − x)/2 across and H/2 up from the pivot, so
  tan α' = (B − x)/H and R' = ½·√((B − x)² + H²);
* the acting bar: b' = b_r − x/2 (b_r = B/2 centred, B external).

The mass and the rotational inertia stay those of the real wall: I' = I_G + m·R'² with
I_G = m·(B² + H²)/12 about the centre of mass, so p'² = m·g·R'/I' (for x = 0, I' = (4/3)·m·R²
and p² = 3g/(4R) as in Eq. 10).  The kernel is unchanged: it sees α', p'², K', θ'_max and
U_r'/I' instead of the edge values.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from frp_assess.dynamics.rebars import Rebars
from frp_assess.dynamics.wall import Wall
from frp_assess.motions.record import G
from frp_assess.rules.bars import bar_force
from frp_assess.rules.masonry import STRESS_BLOCK_FACTOR as STRESS_BLOCK_FACTOR  # re-export
from frp_assess.rules.masonry import base_force, compressed_zone_depth

PivotRule = Literal["edge", "crushing"]
PIVOT_RULES: tuple[PivotRule, ...] = ("edge", "crushing")


def pivot_force(wall: Wall, rebars: Rebars | None) -> float:
    """Largest compression at the pivot N = W + T_u [N/m].

    W = w·B·H; T_u = E·A·ε_max, the acting bar (one face for external bars) at its design
    rupture strain (0 unreinforced).
    """
    if rebars is None:
        return wall.weight
    tension = bar_force(rebars.elastic_modulus, rebars.area(wall), rebars.rupture_strain)
    return base_force(wall.weight, tension)


def pivot_depth(wall: Wall, rebars: Rebars | None, rule: PivotRule) -> float:
    """Depth x [m] of the compressed zone the model pivots in: 0 for ``edge``,
    N/(0.85·f_d) for ``crushing`` (0 when f_d is infinite)."""
    if rule == "edge" or math.isinf(wall.compressive_strength):
        return 0.0
    if rule != "crushing":
        raise ValueError(f"pivot must be one of {PIVOT_RULES}, got {rule!r}")
    return compressed_zone_depth(pivot_force(wall, rebars), wall.compressive_strength)


@dataclass(frozen=True)
class PivotGeometry:
    """The rigid block as the kernel sees it, pivoting at x/2 from its compressed edge.

    Args:
        wall: the real wall.
        rebars: the bars (``None``: unreinforced).
        depth: x [m], 0 ≤ x < B (0: the edge pivot of the paper).
    """

    wall: Wall
    rebars: Rebars | None
    depth: float = 0.0

    def __post_init__(self) -> None:
        if not (math.isfinite(self.depth) and 0.0 <= self.depth < self.wall.thickness):
            raise ValueError(
                f"the compressed zone x = {self.depth:.4g} m is not smaller than the wall "
                f"thickness B = {self.wall.thickness:g} m: the base cannot carry the "
                "compression N = W + T_u, there is no pivot to rock on"
            )

    @property
    def arm(self) -> float:
        """Horizontal distance of the centre of mass from the pivot, (B − x)/2 [m]."""
        return 0.5 * (self.wall.thickness - self.depth)

    @property
    def alpha(self) -> float:
        """Slenderness about the pivot α' [rad], tan α' = (B − x)/H."""
        return math.atan2(2.0 * self.arm, self.wall.height)

    @property
    def R(self) -> float:  # noqa: N802 - the model's symbol
        """Pivot to centre of mass R' = ½·√((B − x)² + H²) [m]."""
        return math.hypot(self.arm, 0.5 * self.wall.height)

    @property
    def inertia(self) -> float:
        """Rotational inertia of the real wall about the pivot, m·(B² + H²)/12 + m·R'²
        [kg·m²/m]."""
        w = self.wall
        return w.mass * ((w.thickness**2 + w.height**2) / 12.0 + self.R**2)

    @property
    def p2(self) -> float:
        """p'² = m·g·R'/I' [rad²/s²]."""
        return self.wall.mass * G * self.R / self.inertia

    @property
    def a_rm(self) -> float:
        """Ground acceleration that starts rocking, g·(B − x)/H [m/s²]."""
        return G * 2.0 * self.arm / self.wall.height

    @property
    def bar_arm(self) -> float:
        """Lever arm of the acting bar about the pivot, b_r − x/2 [m] (0 unreinforced)."""
        if self.rebars is None:
            return 0.0
        return self.rebars.lever_arm(self.wall) - 0.5 * self.depth

    @property
    def K(self) -> float:  # noqa: N802 - the paper's symbol
        """K' of Eq. 10 [-]: bar moment E·A·b'²·sin θ/H over m·g·R' (0 unreinforced).

        For x = 0 it equals sin α·tan α·(r_p/2)·E·A/(m·g) (:meth:`Rebars.stiffness_term`).
        """
        bars = self.rebars
        if bars is None:
            return 0.0
        w = self.wall
        ea = bars.elastic_modulus * bars.area(w)
        return ea * self.bar_arm**2 / (w.height * w.mass * G * self.R)

    @property
    def theta_max(self) -> float:
        """Rupture rotation 2·asin(ε_max·H/(2·b')) [rad]; ``inf``: no bar, or it cannot break."""
        if self.rebars is None:
            return math.inf
        arg = self.rebars.rupture_strain * self.wall.height / (2.0 * self.bar_arm)
        return 2.0 * math.asin(arg) if arg < 1.0 else math.inf

    def elongation(self, theta: float) -> float:
        """Bar elongation 2·b'·sin(|θ|/2) [m] at θ [rad] (Eq. 7 about the pivot)."""
        return 2.0 * self.bar_arm * math.sin(0.5 * abs(theta))

    def strain(self, theta: float) -> float:
        """Strain of the acting bar e/H [-] at θ [rad]."""
        return self.elongation(theta) / self.wall.height

    def strains(self, theta: NDArray[np.float64]) -> NDArray[np.float64]:
        """:meth:`strain` of every rotation in an array [-]."""
        return 2.0 * self.bar_arm * np.sin(0.5 * np.abs(theta)) / self.wall.height

    def stored_energy(self, theta: float) -> float:
        """U_r = ½·(E·A/H)·e² [J/m] at θ [rad] (Eq. 6; 0 unreinforced)."""
        if self.rebars is None:
            return 0.0
        e = self.elongation(theta)
        ea = self.rebars.elastic_modulus * self.rebars.area(self.wall)
        return 0.5 * ea / self.wall.height * e * e
