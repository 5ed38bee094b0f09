"""Masonry at the base of the wall (SI units: m, N, Pa; forces per metre of wall length).

* FC, the confidence factor of a knowledge level (Circolare 2019 Tab. C8.5.IV), and the
  design compressive strength f_d = f_m/(FC·γ_M) (Circolare 2019 §C8.7.1 uses f_m/FC, γ_M = 1).
* The weight of the wall W = w·B·H and the force on its base N = W + T (T: the acting bar's
  tension; vertical inertia neglected), docs/model.md §1.1.
* NTC 2018 §7.8.2.2.1: the compression at the base is carried by a rectangular stress block of
  0.85·f_d over a depth x = N/(0.85·f_d·1 m); its inverse, the force a depth x carries,
  N = 0.85·f_d·x·1 m.

**Outcome policy (one, used everywhere).**  The only refusal the masonry at the base leads to
is a wall whose base cannot carry its own weight: x_W = W/(0.85·f_d) ≥ B
(:func:`base_carries_weight` false).  Such an input is refused as an input error by whoever
builds the model from a case (``assess/wall_model.py``), with :func:`weight_not_carried`
as its message.  Nothing else is refused or dropped for the pivot: a compressed zone that
grows with the bar force is part of the model (docs/model.md §1.1).  The functions here only
decide; they never raise for it.
"""

from __future__ import annotations

import math

#: Stress of the rectangular stress block as a fraction of f_d (NTC 2018 §7.8.2.2.1) [-].
STRESS_BLOCK_FACTOR = 0.85

#: Confidence factor FC by knowledge level (Circolare 2019 §C8.5.4, Tab. C8.5.IV) [-].
CONFIDENCE_FACTORS: dict[str, float] = {"LC1": 1.35, "LC2": 1.20, "LC3": 1.00}
#: The knowledge levels, in order.
KNOWLEDGE_LEVELS: tuple[str, ...] = tuple(CONFIDENCE_FACTORS)


def confidence_factor(knowledge_level: str) -> float:
    """FC [-] of a knowledge level LC1, LC2 or LC3 (Circolare 2019 Tab. C8.5.IV).

    Raises:
        KeyError: an unknown level (the caller names the key of its input).
    """
    return CONFIDENCE_FACTORS[knowledge_level]


def design_strength(mean_strength: float, fc: float, partial_factor: float = 1.0) -> float:
    """Design strength f_d = f_m/(FC·γ_M) [the unit of ``mean_strength``].

    ``partial_factor`` γ_M = 1 (the default) gives f_m/FC, the seismic assessment of existing
    masonry (Circolare 2019 §C8.7.1).
    """
    if partial_factor == 1.0:
        return mean_strength / fc
    return mean_strength / (fc * partial_factor)


def wall_weight(unit_weight: float, thickness: float, height: float) -> float:
    """Weight of the wall per metre of length W = w·B·H [N/m] (w [N/m³], B, H [m];
    docs/model.md §1.1)."""
    return unit_weight * thickness * height


def base_force(weight: float, bar_force: float = 0.0) -> float:
    """Vertical force on the base N = W + T [N/m]: weight W [N/m] and tension T [N/m] of the
    acting bar (docs/model.md §1.1)."""
    return weight + bar_force


def compressed_zone_depth(normal_force: float, design_strength: float) -> float:
    """Depth x [m] of the stress block that carries ``normal_force`` N [N/m] on 1 m of wall:
    x = N / (0.85·f_d·1 m), f_d [Pa]; 0 when f_d is infinite (the paper's edge pivot)."""
    if math.isinf(design_strength):
        return 0.0
    return normal_force / (STRESS_BLOCK_FACTOR * design_strength)


def force_for_depth(depth: float, design_strength: float) -> float:
    """The force N [N/m] a stress block of depth x [m] carries on 1 m of wall,
    N = 0.85·f_d·x·1 m (f_d [Pa]; NTC 2018 §7.8.2.2.1): the inverse of
    :func:`compressed_zone_depth`."""
    return STRESS_BLOCK_FACTOR * design_strength * depth


def crushing_depth(thickness: float, bar_distance: float | None = None) -> float:
    """Depth x [m] at which the toe crushes: the thickness B, or the acting bar's distance from
    the compressed corner when smaller (B/2 centred; a bar inside the compressed zone is not in
    tension), docs/model.md §1.1.  ``bar_distance`` [m], ``None`` unreinforced."""
    return thickness if bar_distance is None else min(thickness, bar_distance)


def toe_crushes(depth: float, thickness: float, bar_distance: float | None = None) -> bool:
    """Whether a compressed zone of depth x [m] crushes the toe of a wall B [m] thick:
    x ≥ :func:`crushing_depth` (docs/model.md §1.1; ``bar_distance`` [m])."""
    return depth >= crushing_depth(thickness, bar_distance)


def base_carries_weight(weight: float, thickness: float, design_strength: float) -> bool:
    """Whether the base carries the wall's own weight: x_W = W/(0.85·f_d) < B (docs/model.md
    §1.1).

    W [N/m], B [m], f_d [Pa] (infinite: always).  False is the one refusal of the module's
    outcome policy.
    """
    return not toe_crushes(compressed_zone_depth(weight, design_strength), thickness)


def weight_not_carried(weight: float, thickness: float, design_strength: float) -> str:
    """The one-line reason a base that cannot carry the wall's weight is refused
    (docs/model.md §1.1): W [N/m], B [m], f_d [Pa]."""
    depth = compressed_zone_depth(weight, design_strength)
    return (
        f"the base cannot carry the wall's weight: W = {weight / 1e3:.1f} kN/m needs "
        f"x = W/(0.85*f_d) = {depth * 1e3:.0f} mm of masonry at f_d = "
        f"{design_strength / 1e6:.3g} MPa, not less than the thickness B = "
        f"{thickness * 1e3:.0f} mm; check the wall's size and the masonry's strength"
    )
