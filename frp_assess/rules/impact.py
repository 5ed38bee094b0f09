"""The energy a rocking block loses at an impact (docs/model.md §3; paper Eqs. 13–14).

Housner (1963): a rectangular block of slenderness α that rocks on a rigid base keeps, at each
impact on its base, the fraction r₂ = (1 − 1.5·sin²α)² of its kinetic energy (angular momentum
conserved about the new corner).  A wall that rebounds off a restraint on one side meets the
base, the restraint and the base again: r₁ = [r₂·(1 − 1.5·cos²α)]² (paper Eq. 14).
"""

from __future__ import annotations

import math


def housner_two_sided(alpha: float) -> float:
    """r₂ = (1 − 1.5·sin²α)² [-] (paper Eq. 13; Housner 1963): kinetic-energy ratio of one
    base impact of a rectangular block of slenderness α [rad]."""
    return (1.0 - 1.5 * math.sin(alpha) ** 2) ** 2


def one_sided(alpha: float) -> float:
    """r₁ = [(1 − 1.5·sin²α)²·(1 − 1.5·cos²α)]² [-] (paper Eq. 14): kinetic-energy ratio of
    the base–wall–base impact sequence of a wall of slenderness α [rad] rebounding off its
    restraint (Housner's r₂ of :func:`housner_two_sided`, once)."""
    return (housner_two_sided(alpha) * (1.0 - 1.5 * math.cos(alpha) ** 2)) ** 2
