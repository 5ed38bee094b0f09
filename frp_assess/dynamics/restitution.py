"""Energy loss at impacts (docs/model.md §3; paper Eqs. 13–14)."""

from __future__ import annotations

import math
from typing import Literal

from frp_assess.dynamics.wall import Mechanism

# the kinetic-energy ratios r₂, r₁ of Eqs. 13–14, written once in rules/ (re-exported)
from frp_assess.rules.impact import housner_two_sided as housner_two_sided
from frp_assess.rules.impact import one_sided as one_sided

Convention = Literal["energy", "velocity"]
#: ``"energy"`` | ``"velocity"`` | an explicit velocity ratio in (0, 1].
Restitution = Convention | float


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
