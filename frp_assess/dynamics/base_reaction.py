"""The base reaction of the rocking wall: a stress block that follows the bars (docs/model.md §1.1).

Everything is per metre of wall length, in SI units (m, N, Pa, rad).

The wall turns about the corner of its base (the kinematics of the paper, Eq. 10).  The base
carries the vertical force N(θ) = W + T(θ) — the wall's weight and the force of the acting,
intact bar, T = E·A·e/H with e = 2·b_r·sin(|θ|/2) (Eq. 7) — on a rectangular stress block of
0.85·f_d (NTC 2018 §7.8.2.2.1) of depth x(θ) = N/(0.85·f_d).  The resultant acts at x/2 from
the corner, so its moment N·(x/2)·cos θ is subtracted from the restoring moment.  Per unit of
the weight moment m·g·R it is ξ·n(θ)²·cos θ with

    n(θ) = N/W = 1 + κ·sin(|θ|/2),   κ = 2·b_r·E·A/(H·W),   ξ = x_W/(2R),   x_W = W/(0.85·f_d).

``pivot: edge`` (the paper) is f_d → ∞: x = 0, ξ = 0.  ``pivot: crushing`` keeps f_d.

The toe crushes when x reaches the acting bar's distance from the corner, d = b_r (B/2
centred, B external; a bar inside the compressed zone cannot be in tension):
sin(θ_cr/2) = (d/x_W − 1)/κ.  The angle where the unreinforced wall's restoring moment
vanishes, R·sin(α − θ) = (x_W/2)·cos θ, is α_x = atan((B − x_W)/H).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from frp_assess.dynamics.rebars import Rebars
from frp_assess.dynamics.wall import Wall
from frp_assess.rules.constants import G
from frp_assess.rules.geometry import slenderness
from frp_assess.rules.masonry import (
    base_carries_weight,
    compressed_zone_depth,
    weight_not_carried,
)

PivotRule = Literal["edge", "crushing"]
PIVOT_RULES: tuple[PivotRule, ...] = ("edge", "crushing")


@dataclass(frozen=True)
class BaseReaction:
    """The base reaction of one wall with its bars under a pivot rule.

    Args:
        wall: the wall (its :attr:`Wall.compressive_strength` is f_d [Pa]).
        rebars: the bars (``None``: unreinforced).
        rule: ``"crushing"`` (the stress block of f_d) or ``"edge"`` (x = 0).

    Raises:
        ValueError: with ``crushing``, when x_W ≥ B (the base cannot carry the wall's weight).
    """

    wall: Wall
    rebars: Rebars | None
    rule: PivotRule = "crushing"
    #: Σ P_i [N/m], the vertical loads on the wall's top (docs/model.md §12): the base carries
    #: N₀ = W + Σ P_i at rest, so x₀ = N₀/(0.85·f_d), and ξ, κ below are scaled to N₀
    vertical_load: float = 0.0

    def __post_init__(self) -> None:
        if self.rule not in PIVOT_RULES:
            raise ValueError(f"pivot must be one of {PIVOT_RULES}, got {self.rule!r}")
        w = self.wall
        n0 = self.normal_force
        if self.rule == "crushing" and not base_carries_weight(
            n0, w.thickness, w.compressive_strength
        ):
            raise ValueError(weight_not_carried(n0, w.thickness, w.compressive_strength))

    @property
    def weight(self) -> float:
        """W = w·B·H [N/m]."""
        return self.wall.weight

    @property
    def normal_force(self) -> float:
        """N₀ = W + Σ P_i [N/m]: the vertical force on the base at rest."""
        return self.weight + self.vertical_load

    @property
    def weight_depth(self) -> float:
        """x₀ = N₀/(0.85·f_d) [m], the stress block at rest (x_W = W/(0.85·f_d) without loads;
        0: edge)."""
        if self.rule == "edge":
            return 0.0
        return compressed_zone_depth(self.normal_force, self.wall.compressive_strength)

    @property
    def xi(self) -> float:
        """ξ [-]: the reaction moment at rest N₀·x₀/2 over m·g·R, x_W/(2R) without loads."""
        if self.vertical_load == 0.0:
            return self.weight_depth / (2.0 * self.wall.R)
        return self.weight_depth * self.normal_force / (2.0 * self.wall.R * self.weight)

    @property
    def kappa(self) -> float:
        """κ = 2·b_r·E·A/(H·W) [-]: the acting bar's force over W per unit sin(|θ|/2)
        (0 unreinforced, and with the edge pivot, where it does not enter)."""
        bars = self.rebars
        if bars is None or self.xi == 0.0:
            return 0.0
        w = self.wall
        ea = bars.elastic_modulus * bars.area(w)
        return 2.0 * bars.lever_arm(w) * ea / (w.height * self.normal_force)

    @property
    def bar_distance(self) -> float | None:
        """The acting bar's distance from the corner, b_r [m] (``None`` unreinforced)."""
        return None if self.rebars is None else self.rebars.lever_arm(self.wall)

    @property
    def crushing_rotation(self) -> float:
        """θ_cr [rad]: |θ| at which x reaches the intact acting bar, sin(θ_cr/2) =
        (d/x_W − 1)/κ; 0 when x_W ≥ d already (the toe crushes at the first uplift);
        ``inf`` when it never does (no bar, the edge pivot, or an argument ≥ 1)."""
        d = self.bar_distance
        x_w = self.weight_depth
        if d is None or x_w == 0.0:
            return math.inf
        if x_w >= d:
            return 0.0
        arg = (d / x_w - 1.0) / self.kappa
        return 2.0 * math.asin(arg) if arg < 1.0 else math.inf

    @property
    def alpha_x(self) -> float:
        """α_x = atan((B − x_W)/H) [rad]: where the unreinforced wall stops resisting
        (the wall's α with the edge pivot)."""
        if self.weight_depth == 0.0:
            return self.wall.alpha
        w = self.wall
        return slenderness(w.thickness - self.weight_depth, w.height)  # tan α_x = (B − x_W)/H

    @property
    def tan_alpha_x(self) -> float:
        """tan α_x = (B − x_W)/H [-] (tan α computed as sin α/cos α with the edge pivot)."""
        if self.weight_depth == 0.0:
            a = self.wall.alpha
            return math.sin(a) / math.cos(a)
        w = self.wall
        return (w.thickness - self.weight_depth) / w.height

    @property
    def a_rm(self) -> float:
        """Ground acceleration that starts rocking, g·(B − x_W)/H [m/s²] (the bars, unstressed
        at rest, do not change it; g·tan α with the edge pivot)."""
        if self.weight_depth == 0.0:
            return self.wall.a_rm
        return G * self.tan_alpha_x

    def force(
        self, theta: float | NDArray[np.float64], bar_intact: bool = True
    ) -> NDArray[np.float64]:
        """N(θ) = W + T(θ) [N/m] at θ [rad] (T = 0 with no intact bar)."""
        t = np.abs(np.asarray(theta, dtype=np.float64))
        bars = self.rebars
        if bars is None or not bar_intact:
            return np.full_like(t, self.normal_force)
        ea = bars.elastic_modulus * bars.area(self.wall)
        return self.normal_force + ea * bars.elongation(self.wall, t) / self.wall.height

    def depth(
        self, theta: float | NDArray[np.float64], bar_intact: bool = True
    ) -> NDArray[np.float64]:
        """x(θ) = N(θ)/(0.85·f_d) [m] (0 with the edge pivot)."""
        if self.weight_depth == 0.0:
            return np.zeros_like(np.asarray(theta, dtype=np.float64))
        return self.force(theta, bar_intact) * (self.weight_depth / self.normal_force)
