"""Energy loss at impacts (docs/model.md §3; paper Eqs. 13–14)."""

from __future__ import annotations

import math
from typing import Literal

from frp_assess.dynamics.wall import Mechanism

Convention = Literal["energy", "velocity"]
#: ``"energy"`` | ``"velocity"`` | an explicit velocity ratio in (0, 1].
Restitution = Convention | float


def housner_two_sided(alpha: float) -> float:
    """r₂ = (1 − 1.5·sin²α)² (paper Eq. 13; Housner 1963): kinetic-energy ratio of one
    base impact of a rectangular block."""
    return (1.0 - 1.5 * math.sin(alpha) ** 2) ** 2


def one_sided(alpha: float) -> float:
    """r₁ = [(1 − 1.5·sin²α)²·(1 − 1.5·cos²α)]² (paper Eq. 14): kinetic-energy ratio of the
    base–wall–base impact sequence of a wall rebounding off its restraint."""
    return ((1.0 - 1.5 * math.sin(alpha) ** 2) ** 2 * (1.0 - 1.5 * math.cos(alpha) ** 2)) ** 2


def velocity_ratio(restitution: Restitution, mechanism: Mechanism, alpha: float) -> float:
    """|θ'₊|/|θ'₋| applied at an impact.

    ``"energy"`` (default) reads Eqs. 13–14 as kinetic-energy ratios: √r;
    ``"velocity"`` applies r to the velocity as the paper's sentence literally reads;
    a number is the velocity ratio itself.
    """
    if isinstance(restitution, str):
        r = one_sided(alpha) if mechanism == "one-sided" else housner_two_sided(alpha)
        if restitution == "energy":
            return math.sqrt(r)
        if restitution == "velocity":
            return r
        raise ValueError(
            f"restitution must be 'energy', 'velocity' or a number, got {restitution!r}"
        )
    value = float(restitution)
    if not (math.isfinite(value) and 0.0 < value <= 1.0):
        raise ValueError(f"restitution velocity ratio must be in (0, 1], got {restitution!r}")
    return value
