"""Steel tie-rods (catene) holding a façade at a floor, per metre of wall (SI: m, N, Pa).

A tie is anchored on the outer face at height h_t by a plate; it works in tension only, is
elastic–perfectly plastic in the steel (yield f_y) and may lose its anchorage (the plate
punching the masonry) before the steel yields (docs/model.md §12).  With ties every i_t metres
along the wall, a tie of area A_s and free length L_t gives per metre of wall

* the stiffness k_t = E_s·A_s/(L_t·i_t) [N/m per m],
* the yield force F_y = A_s·f_y/i_t [N/m],
* the anchorage force F_a/i_t [N/m] (∞ when the anchorage is not governing).

Sources: Circolare 2019 §C8.7.1.2 (the tie's work in the kinematic analysis); EN 10025-2
(S235: f_y = 235 MPa) and EN 1993-1-1 §3.2.6 (E = 210 GPa) for the defaults.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

#: f_y of S235 steel, the usual steel of existing and new ties (EN 10025-2) [Pa].
DEFAULT_YIELD_STRENGTH = 235e6
#: E of structural steel (EN 1993-1-1 §3.2.6) [Pa].
DEFAULT_ELASTIC_MODULUS = 210e9
#: density of steel, ρ = 7850 kg/m³ (78.5 kN/m³, the upper value of EN 1991-1-1 Table A.4)
STEEL_DENSITY = 7850.0


def tie_steel_mass(area: float, length: float, spacing: float) -> float:
    """Steel of the ties per metre of wall, ρ·A_s·L_t/i_t [kg/m]: one bar of area A_s [m²] and
    free length L_t [m] every i_t [m] along the wall (the anchorages' plates not counted;
    ρ of EN 1991-1-1 Table A.4; docs/model.md §12)."""
    return STEEL_DENSITY * area * length / spacing


def round_bar_area(diameter: float) -> float:
    """Area of a tie's round bar A_s = π·d²/4 [m²] (d [m]; docs/model.md §12)."""
    return math.pi * diameter * diameter / 4.0


def tie_stiffness(area: float, elastic_modulus: float, length: float, spacing: float) -> float:
    """Axial stiffness of the ties per metre of wall k_t = E_s·A_s/(L_t·i_t) [N/m per m]
    (docs/model.md §12).

    Args:
        area: A_s [m²] of one tie.
        elastic_modulus: E_s [Pa].
        length: L_t [m], free length of the tie between its anchorages.
        spacing: i_t [m], distance between ties along the wall.
    """
    return elastic_modulus * area / (length * spacing)


def tie_yield_force(area: float, yield_strength: float, spacing: float) -> float:
    """Force at which the ties yield, per metre of wall F_y = A_s·f_y/i_t [N/m]
    (docs/model.md §12)."""
    return area * yield_strength / spacing


def tie_anchorage_force(anchorage: float | None, spacing: float) -> float:
    """Force at which the anchorage of the ties fails, per metre of wall F_a/i_t [N/m]
    (docs/model.md §12).

    ``anchorage`` F_a [N] is the capacity of one tie's anchorage (the plate punching the
    masonry); ``None``: not governing, ∞.
    """
    if anchorage is None:
        return math.inf
    return anchorage / spacing


def tie_capacity(yield_force: float, anchorage_force: float) -> float:
    """The largest force the ties carry, min(F_y, F_a/i_t) [N/m] (Circolare 2019
    §C8.7.1.2: the tie's force at collapse in the kinematic analysis)."""
    return min(yield_force, anchorage_force)


def tie_is_ductile(yield_force: float, anchorage_force: float) -> bool:
    """Whether the steel yields before the anchorage fails (F_y < F_a/i_t): a ductile tie,
    whose force is surely present up to collapse (it counts in d0, docs/model.md §12) [-]."""
    return yield_force < anchorage_force


def tie_elongation(height: float, theta: float) -> float:
    """Elongation of a tie at height h_t [m] of a wall turned by θ [rad] outward about its
    outer base corner, δ = h_t·sin θ [m] for θ > 0; 0 for θ ≤ 0 (the tie goes slack;
    docs/model.md §12)."""
    return height * math.sin(theta) if theta > 0.0 else 0.0


def tie_force(
    stiffness: float,
    yield_force: float,
    elongation: float,
    plastic_elongation: float,
) -> float:
    """Force of an elastic–perfectly plastic, tension-only tie [N/m]:
    F_t = clip(k_t·(δ − δ_p), 0, F_y), δ_p the plastic elongation [m] left by earlier yields
    (docs/model.md §12)."""
    return min(max(stiffness * (elongation - plastic_elongation), 0.0), yield_force)


def tie_elongations(
    stiffness: float, yield_force: float, anchorage_force: float
) -> tuple[float, float]:
    """(δ_y, δ_a) [m]: the elongation beyond δ_p at which the ties yield, F_y/k_t, and at which
    a brittle anchorage fails, F_a/k_t (∞ for a ductile tie, whose force never exceeds F_y;
    docs/model.md §12).  Per metre of wall or per tie alike: spacing and area cancel,
    δ_y = f_y·L_t/E_s."""
    loss = math.inf
    if not tie_is_ductile(yield_force, anchorage_force):
        loss = anchorage_force / stiffness
    return yield_force / stiffness, loss


#: Tie levels the time histories hold (docs/model.md §12): ties at different heights, or
#: yielding or losing their anchorage at different elongations, are different levels.
MAX_TIE_LEVELS = 2
#: What the time histories need of several ties, for the messages.
TIE_LEVELS_RULE = (
    f"at most {MAX_TIE_LEVELS} tie levels; ties at the same height whose steel yields and "
    "whose anchorage fails at the same elongation (the same f_y·L_t/E_s and F_a·L_t/(E_s·A_s)) "
    "are one level"
)
#: Relative difference below which two ties' heights and elongations are the same [-].
SAME_LEVEL = 1e-9


def same_tie_level(
    a: tuple[float, float, float, float], b: tuple[float, float, float, float]
) -> bool:
    """Whether two ties, each (h_t [m], k_t [N/m per m], F_y [N/m], F_a/i_t [N/m]), act as one
    and may be summed [-]: at the same height, yielding and losing their anchorage at the same
    elongations
    (:func:`tie_elongations`): one level of the time histories (docs/model.md §12)."""

    def close(x: float, y: float) -> bool:
        if math.isinf(x) or math.isinf(y):
            return x == y
        return abs(x - y) <= SAME_LEVEL * max(abs(x), abs(y))

    ea, eb = tie_elongations(*a[1:]), tie_elongations(*b[1:])
    return close(a[0], b[0]) and close(ea[0], eb[0]) and close(ea[1], eb[1])


def tie_level_of_each(ties: Sequence[tuple[float, float, float, float]]) -> list[int]:
    """The level of each tie, each (h_t [m], k_t [N/m per m], F_y [N/m], F_a/i_t [N/m]): 0
    for the first tie and every tie that acts as one with it (:func:`same_tie_level`), then
    1 for the next tie that does not, and so on, in the order given: the tie levels of the
    time histories (docs/model.md §12)."""
    firsts: list[tuple[float, float, float, float]] = []
    levels = []
    for t in ties:
        for j, first in enumerate(firsts):
            if same_tie_level(first, t):
                levels.append(j)
                break
        else:
            firsts.append(t)
            levels.append(len(firsts) - 1)
    return levels
