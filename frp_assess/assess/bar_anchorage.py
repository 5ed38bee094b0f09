"""Bars as they are built: the anchorage of a bar and the masonry pull-out cone.

Units: diameters [mm], bar areas [mm²], lengths and spacings [m], ratios [‰], forces [kN],
stresses [MPa], E [GPa], density [kg/m³], price [currency/kg].

**Anchorage.** The design force per bar at rupture is F = A_b·E·ε (A_b [mm²]·E [GPa]·ε gives
kN).  A bar bonded in a resin-filled hole of diameter d_h needs the bond length

    l_b = max( F / (π·d·τ_b),  F / (π·d_h·τ_m) )

for the bar–resin interface (bond strength τ_b) and the resin–masonry interface (τ_m): the
equilibrium of a uniform bond stress along the bar, the form of the anchorage length of
FRP bars in CNR-DT 203/2006 and ACI 440.1R (l_b = d·f/(4·τ)).  The bond strengths come from
the producer's tests (τ_b) and from pull-out tests on the masonry (τ_m); they are inputs,
no default is assumed.  The masonry pull-out cone is a check: a 45° cone from the end of
the bond length, projected area π·l_b² (TMS 402 anchor bolts in masonry, A_pt = π·l_b²),
clipped by the faces of the wall and shared with the neighbouring bars (its base is limited
to the strip of width s around the bar), with the tensile strength f_t = 1.5·τ0d of the
masonry (the Turnšek–Čačovič relation behind the diagonal-cracking shear strength of
Circolare 2019 §C8.7.1).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from scipy.integrate import quad

from frp_assess.dynamics import Position
from frp_assess.rules import bars as rule

# ---------------------------------------------------------------------------------------------
# Anchorage


def bar_rupture_force(bar_area: float, elastic_modulus: float, strain: float) -> float:
    """Force in one bar, F = A_b·E·ε [kN] (A_b [mm²], E [GPa]: mm²·GPa = kN)."""
    return rule.bar_force(elastic_modulus, bar_area, strain)


def cone_area(radius: float, face_distances: tuple[float, float], spacing: float) -> float:
    """Projected area [m²] of a cone base of ``radius`` [m] around a bar, clipped to the wall
    (``face_distances`` [m] from the bar's axis to each face) and to the strip of width
    ``spacing`` [m] it shares with its neighbours."""
    if not (radius >= 0 and spacing > 0 and min(face_distances) >= 0):
        raise ValueError("radius, face distances must be >= 0 and spacing > 0")
    a = max(-face_distances[0], -radius)
    b = min(face_distances[1], radius)
    if b <= a:
        return 0.0
    half = 0.5 * spacing

    def width(x: float) -> float:
        return 2.0 * min(math.sqrt(max(radius * radius - x * x, 0.0)), half)

    points = []
    if half < radius:
        x_k = math.sqrt(radius * radius - half * half)
        points = [p for p in (-x_k, x_k) if a < p < b]
    value, _ = quad(width, a, b, points=points or None, limit=200)
    return value


@dataclass(frozen=True)
class Anchorage:
    """Anchorage of one bar in a resin-filled hole, and the masonry pull-out cone check.

    Attributes:
        force: F [kN].
        length_bar: F/(π·d·τ_b) [m].  length_masonry: F/(π·d_h·τ_m) [m].
        length_required: the larger [m].  length: the length provided [m] (the required one
            unless given).
        cone_area: projected area of the 45° cone [m²].
        tensile_strength: f_t [MPa].
        cone_resistance: f_t·area [kN].
        cone_ok: cone_resistance ≥ F.
        length_ok: length ≥ length_required.
    """

    force: float
    length_bar: float
    length_masonry: float
    length_required: float
    length: float
    cone_area: float
    tensile_strength: float
    cone_resistance: float
    cone_ok: bool
    length_ok: bool


def anchorage(
    force: float,
    diameter: float,
    *,
    hole_diameter: float,
    bond_bar: float,
    bond_masonry: float,
    tensile_strength: float,
    thickness: float,
    spacing: float,
    position: Position,
    axis_to_face: float = 0.0,
    length: float | None = None,
) -> Anchorage:
    """Bond length and pull-out cone for a bar force ``force`` [kN] (module docstring).

    Args:
        diameter: d [mm].  hole_diameter: d_h [mm] (≥ d).
        bond_bar: τ_b, bar–resin [MPa].  bond_masonry: τ_m, resin–masonry [MPa].
        tensile_strength: f_t of the masonry [MPa], e.g. 1.5·τ0d.
        thickness: B [m].  spacing: s between bars of the line [m].
        position: ``centred`` (axis at B/2) or ``external`` (axis ``axis_to_face`` [m] from
            its face, e.g. half the groove depth).
        length: bond length provided [m]; the required length when omitted.
    """
    if not (force >= 0 and diameter > 0 and hole_diameter >= diameter):
        raise ValueError("need force >= 0, diameter > 0 and hole_diameter >= diameter")
    if not (bond_bar > 0 and bond_masonry > 0 and tensile_strength > 0):
        raise ValueError("bond strengths and tensile strength must be > 0 MPa")
    newton = force * 1e3
    l_bar = newton / (math.pi * diameter * bond_bar) * 1e-3  # N / (mm·MPa) = mm → m
    l_mas = newton / (math.pi * hole_diameter * bond_masonry) * 1e-3
    required = max(l_bar, l_mas)
    provided = required if length is None else length
    if position == "centred":
        faces = (0.5 * thickness, 0.5 * thickness)
    elif position == "external":
        if not 0 <= axis_to_face <= thickness:
            raise ValueError(f"axis_to_face must be within the wall, got {axis_to_face}")
        faces = (axis_to_face, thickness - axis_to_face)
    else:
        raise ValueError(f"position must be 'centred' or 'external', got {position!r}")
    area = cone_area(provided, faces, spacing)
    resistance = tensile_strength * 1e3 * area  # MPa·m² = MN → kN
    return Anchorage(
        force=force,
        length_bar=l_bar,
        length_masonry=l_mas,
        length_required=required,
        length=provided,
        cone_area=area,
        tensile_strength=tensile_strength,
        cone_resistance=resistance,
        cone_ok=bool(resistance >= force),
        length_ok=bool(provided >= required * (1.0 - 1e-12)),
    )
