"""The rigid rocking wall (docs/model.md §1; paper Eqs. 2–5).

Everything is per metre of wall length and in SI units (m, kg, N, s, rad).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from frp_assess.rules.constants import G
from frp_assess.rules.geometry import (
    half_diagonal,
    size_problem,
    slenderness,
    slenderness_problem,
    thickness_of,
)
from frp_assess.rules.masonry import wall_weight

Mechanism = Literal["one-sided", "two-sided"]
MECHANISMS: tuple[Mechanism, ...] = ("one-sided", "two-sided")


@dataclass(frozen=True)
class Wall:
    """A monolithic rectangular masonry block rocking about its base corners.

    Args:
        thickness: B [m], out-of-plane thickness.
        height: H [m].
        unit_weight: w [N/m³] (18 kN/m³ = 18e3 N/m³ for solid brick and lime mortar).
        compressive_strength: design compressive strength of the masonry f_d [Pa]; only the
            ``crushing`` pivot uses it (docs/model.md §1.1); ``inf``: the masonry never
            crushes, the pivot stays at the edge.
    """

    thickness: float
    height: float
    unit_weight: float
    compressive_strength: float = math.inf

    def __post_init__(self) -> None:
        for name in ("thickness", "height", "unit_weight"):
            value = getattr(self, name)
            if size_problem(value) is not None:
                raise ValueError(f"wall {name} must be a finite number > 0, got {value!r}")
        if not self.compressive_strength > 0.0:  # inf allowed, nan refused
            raise ValueError(
                f"wall compressive strength must be > 0 Pa, got {self.compressive_strength!r}"
            )
        if (problem := slenderness_problem(self.thickness, self.height)) is not None:
            raise ValueError(f"wall: {problem}")

    @property
    def alpha(self) -> float:
        """Slenderness angle α [rad], tan α = B/H."""
        return slenderness(self.thickness, self.height)

    @property
    def R(self) -> float:  # noqa: N802 - the model's symbol
        """Half diagonal R [m] = ½·√(B² + H²): centre of mass to a base corner."""
        return half_diagonal(self.thickness, self.height)

    @property
    def mass(self) -> float:
        """Mass per metre of wall m = w·B·H/g [kg/m]."""
        return self.weight / G

    @property
    def weight(self) -> float:
        """Weight per metre of wall W = w·B·H [N/m]."""
        return wall_weight(self.unit_weight, self.thickness, self.height)

    @property
    def I0(self) -> float:  # noqa: N802
        """Polar moment of inertia about a base corner, (4/3)·m·R² [kg·m²/m]."""
        return 4.0 / 3.0 * self.mass * self.R**2

    @property
    def p2(self) -> float:
        """Frequency parameter p² = m·g·R/I0 = 3g/(4R) [rad²/s²]."""
        return 3.0 * G / (4.0 * self.R)

    @property
    def p(self) -> float:
        """Frequency parameter p [rad/s]."""
        return math.sqrt(self.p2)

    @property
    def a_rm(self) -> float:
        """Ground acceleration that activates rocking, g·tan α [m/s²]."""
        return G * self.thickness / self.height

    @property
    def a_rm_g(self) -> float:
        """Ground acceleration that activates rocking, tan α [g]."""
        return self.thickness / self.height

    @classmethod
    def from_slenderness(cls, height: float, alpha: float, unit_weight: float) -> Wall:
        """The wall of height H [m] and slenderness α [rad] (B = H·tan α)."""
        return cls(thickness_of(height, alpha), height, unit_weight)
