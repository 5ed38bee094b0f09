"""Unbonded vertical FRP rebars restraining the rocking wall (docs/model.md §2; paper Eqs. 6–11)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import overload

import numpy as np
from numpy.typing import NDArray

from frp_assess import libm
from frp_assess.dynamics.wall import Wall
from frp_assess.rules import bars as rule
from frp_assess.rules.bars import DEFAULT_STRAIN_FACTOR as DEFAULT_STRAIN_FACTOR  # re-export
from frp_assess.rules.bars import POSITIONS as POSITIONS
from frp_assess.rules.bars import Position as Position


@dataclass(frozen=True)
class Rebars:
    """One layer of vertical FRP rebars: material, position and ratio.

    Args:
        elastic_modulus: E [Pa].
        ultimate_strain: ε_u [-].
        position: ``"centred"`` (in the mid-plane of the wall) or ``"external"`` (on both faces).
        ratio: ρ [‰], area of the *active* bars per metre as a fraction of the wall section B·1 m.
            External bars carry this area on each face (installed quantity 2·A).
        strain_factor: c [-], the design rupture strain is ε_max = c·ε_u.
    """

    elastic_modulus: float
    ultimate_strain: float
    position: Position
    ratio: float
    strain_factor: float = DEFAULT_STRAIN_FACTOR

    def __post_init__(self) -> None:
        if not (math.isfinite(self.elastic_modulus) and self.elastic_modulus > 0.0):
            raise ValueError(f"elastic modulus must be > 0 Pa, got {self.elastic_modulus!r}")
        if not (math.isfinite(self.ultimate_strain) and 0.0 < self.ultimate_strain < 1.0):
            raise ValueError(f"ultimate strain must be in (0, 1), got {self.ultimate_strain!r}")
        if self.position not in POSITIONS:
            raise ValueError(f"position must be 'centred' or 'external', got {self.position!r}")
        if not (math.isfinite(self.ratio) and 0.0 < self.ratio <= rule.MAX_RATIO):
            raise ValueError(
                f"ratio must be in (0, {rule.MAX_RATIO:g}] per mille, got {self.ratio!r}"
            )
        if not (math.isfinite(self.strain_factor) and 0.0 < self.strain_factor <= 1.0):
            raise ValueError(f"strain factor must be in (0, 1], got {self.strain_factor!r}")

    @property
    def r_p(self) -> float:
        """Position factor r_p of Eq. 10: 1 centred, 4 external."""
        return 1.0 if self.position == "centred" else 4.0

    @property
    def rupture_strain(self) -> float:
        """Design rupture strain ε_max = c·ε_u [-]."""
        return rule.rupture_strain(self.ultimate_strain, self.strain_factor)

    def lever_arm(self, wall: Wall) -> float:
        """b_r [m]: R·sin α = B/2 centred (Eq. 8), 2R·sin α = B external (Eq. 9)."""
        return rule.lever_arm(self.position, wall.thickness)

    def area(self, wall: Wall) -> float:
        """A [m² per metre of wall]: active bar area, ρ·B·(1 m)."""
        return rule.bar_area(self.ratio, wall.thickness)

    def installed_area(self, wall: Wall) -> float:
        """Installed bar area [m² per metre of wall]: A centred, 2·A external (both faces)."""
        return self.area(wall) * rule.faces(self.position)

    def stiffness_term(self, wall: Wall) -> float:
        """K [-] of Eq. 10: sin α · tan α · (r_p/2) · E·A/(m·g)."""
        a = wall.alpha
        ea_over_mg = self.elastic_modulus * self.area(wall) / wall.weight
        return math.sin(a) * math.tan(a) * 0.5 * self.r_p * ea_over_mg

    def rupture_rotation(self, wall: Wall) -> float:
        """θ_max [rad] = 2·asin(ε_max·H/(2·b_r)) (Eq. 11); ``inf`` if the bar cannot break."""
        arg = self.rupture_strain * wall.height / (2.0 * self.lever_arm(wall))
        return 2.0 * math.asin(arg) if arg < 1.0 else math.inf

    @overload
    def elongation(self, wall: Wall, theta: float) -> float: ...
    @overload
    def elongation(self, wall: Wall, theta: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def elongation(
        self, wall: Wall, theta: float | NDArray[np.float64]
    ) -> float | NDArray[np.float64]:
        """e [m] = 2·b_r·sin(|θ|/2) (Eq. 7); θ [rad], a number or an array."""
        if isinstance(theta, np.ndarray):
            return 2.0 * self.lever_arm(wall) * libm.sin(0.5 * np.abs(theta))
        return 2.0 * self.lever_arm(wall) * math.sin(0.5 * abs(theta))

    @overload
    def strain(self, wall: Wall, theta: float) -> float: ...
    @overload
    def strain(self, wall: Wall, theta: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def strain(self, wall: Wall, theta: float | NDArray[np.float64]) -> float | NDArray[np.float64]:
        """Strain of the acting bar e/H [-] (free length H) at θ [rad], a number or an array."""
        return self.elongation(wall, theta) / wall.height

    def stored_energy(self, wall: Wall, theta: float) -> float:
        """U_r [J per metre of wall] = ½·(E·A/H)·e² = ¼·e²·E·A/(R·cos α) (Eq. 6)."""
        e = self.elongation(wall, theta)
        return 0.5 * self.elastic_modulus * self.area(wall) / wall.height * e * e
