"""The ``wall.loads`` block: what bears on and pushes the wall (docs/model.md §12).

Every force is per metre of wall length (kN/m), every length in m from the wall's rocking
base (heights) or from its outer face (the line of action of a top load), the face the
façade falls away from.  A tie's own quantities are per tie (its diameter or area, its
anchorage's capacity) with the spacing i_t along the wall that turns them into per metre.
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field, model_validator

from frp_assess.config.schema.spec_base import Number, _Model, located_error
from frp_assess.rules.tie_rods import (
    MAX_TIE_LEVELS,
    TIE_LEVELS_RULE,
    tie_anchorage_force,
    tie_level_of_each,
    tie_stiffness,
    tie_yield_force,
)

#: the name of a load in the outputs
_NAME = Field(
    "",
    max_length=80,
    description="Name of the load in the outputs (text, at most 80 characters; default: "
    "its kind and position in the list).",
)
#: the largest load [kN/m]: a six-storey floor load on a metre of wall is ~200 kN/m
MAX_LOAD = 2000.0
#: the largest tie diameter [mm]: existing ties are 20-40 mm round bars
MAX_TIE_DIAMETER = 80.0
Inertia = Literal["carried", "restrained"]


class TopLoadSpec(_Model):
    """A vertical load bearing on the top of the wall (a floor, the roof)."""

    name: str = _NAME
    load: Number = Field(
        gt=0, le=MAX_LOAD, description="P [kN/m], the vertical load per metre of wall, 0-2000."
    )
    distance: Number = Field(
        ge=0,
        description="d [m], its line of action from the outer face, 0 <= d <= B (a floor "
        "bearing on part of the thickness acts inside it).",
    )
    inertia: Inertia = Field(
        "carried",
        description="carried (default): the load's mass moves horizontally with the top of the "
        "wall (a floor not held elsewhere); restrained: a vertical force only (the floor is "
        "held horizontally by other walls).",
    )


class ThrustSpec(_Model):
    """A horizontal force pushing the wall outward on its inner face (a roof, a vault)."""

    name: str = _NAME
    force: Number = Field(
        gt=0, le=MAX_LOAD, description="F [kN/m], the outward thrust per metre of wall, 0-2000."
    )
    height: Number = Field(ge=0, description="h [m] above the rocking base, 0 <= h <= H.")


class TieSpec(_Model):
    """A steel tie-rod anchored on the outer face (tension only, elastic–perfectly plastic,
    its anchorage brittle; docs/model.md §12)."""

    name: str = _NAME
    height: Number = Field(gt=0, description="h_t [m] above the rocking base, 0 < h_t <= H.")
    diameter: Number | None = Field(
        None,
        ge=4,
        le=MAX_TIE_DIAMETER,
        description="Bar diameter [mm], 4-80 (or give area).",
    )
    area: Number | None = Field(
        None, gt=0, le=5100, description="Bar area A_s [mm2], up to 5100 (Ø80; or give diameter)."
    )
    spacing: Number = Field(
        ge=0.2, le=50, description="i_t [m], distance between ties along the wall, 0.2-50."
    )
    length: Number = Field(
        ge=0.5, le=100, description="L_t [m], free length of the tie between anchorages, 0.5-100."
    )
    yield_strength: Number = Field(
        235, ge=100, le=1500, description="f_y [MPa] of the steel, 100-1500 (235: S235)."
    )
    elastic_modulus: Number = Field(
        210, ge=100, le=250, description="E_s [GPa] of the steel, 100-250 (210)."
    )
    anchorage: Number | None = Field(
        None,
        gt=0,
        le=5000,
        description="F_a [kN per tie], capacity of the anchorage (the plate punching the "
        "masonry); omit when it does not govern.",
    )

    @model_validator(mode="after")
    def _one_size(self) -> TieSpec:
        if (self.diameter is None) == (self.area is None):
            raise located_error(
                "give the tie's 'diameter' [mm] or its 'area' [mm2], exactly one; found "
                + ("both" if self.diameter is not None else "neither")
            )
        return self

    @property
    def area_mm2(self) -> float:
        """A_s [mm²]: the given area, else π·d²/4."""
        if self.area is not None:
            return float(self.area)
        assert self.diameter is not None
        return 3.141592653589793 * float(self.diameter) ** 2 / 4.0

    def per_metre(self) -> tuple[float, float, float, float]:
        """(h_t [m], k_t [N/m per m], F_y [N/m], F_a/i_t [N/m]) of :mod:`frp_assess.rules.
        tie_rods`, for the check that several ties act as one level."""
        area = self.area_mm2 * 1e-6
        spacing = float(self.spacing)
        anchorage = None if self.anchorage is None else float(self.anchorage) * 1e3
        return (
            float(self.height),
            tie_stiffness(area, float(self.elastic_modulus) * 1e9, float(self.length), spacing),
            tie_yield_force(area, float(self.yield_strength) * 1e6, spacing),
            tie_anchorage_force(anchorage, spacing),
        )


class WallLoadsSpec(_Model):
    """What bears on and pushes the wall (docs/model.md §12); omit for a free-standing wall."""

    top: list[TopLoadSpec] = Field(
        default_factory=list,
        max_length=20,
        description="Vertical loads on the top of the wall: [{load: kN/m, distance: m from the "
        "outer face, inertia: carried | restrained}].",
    )
    thrust: list[ThrustSpec] = Field(
        default_factory=list,
        max_length=20,
        description="Outward thrusts on the inner face: [{force: kN/m, height: m}].",
    )
    ties: list[TieSpec] = Field(
        default_factory=list,
        max_length=10,
        description="Steel tie-rods: [{height: m, diameter: mm (or area: mm2), spacing: m, "
        "length: m, yield_strength: MPa (235), elastic_modulus: GPa (210), anchorage: kN per "
        "tie (optional)}]; at most two levels (e.g. a floor tie and an eaves tie): ties at the "
        "same height that yield and lose their anchorage at the same elongation are one level.",
    )

    def problem(self, thickness: float, height: float) -> tuple[str, tuple[str | int, ...]] | None:
        """The first load outside the wall, as (message, location inside ``loads``): a line of
        action outside the thickness, a thrust or a tie above the top, a third tie level (the
        time histories hold two); ``None`` if all fit."""
        for i, p in enumerate(self.top):
            if p.distance > thickness:
                return (
                    f"expected 0 <= distance <= B = {thickness:g} m (the line of action inside "
                    f"the wall), found {p.distance:g}",
                    ("top", i, "distance"),
                )
        for i, f in enumerate(self.thrust):
            if f.height > height:
                return (
                    f"expected 0 <= height <= H = {height:g} m, found {f.height:g}",
                    ("thrust", i, "height"),
                )
        for i, t in enumerate(self.ties):
            if t.height > height:
                return (
                    f"expected a tie on the wall, 0 < height <= H = {height:g} m, found "
                    f"{t.height:g}",
                    ("ties", i, "height"),
                )
        of_each = tie_level_of_each([t.per_metre() for t in self.ties])
        for i, level in enumerate(of_each):
            if level >= MAX_TIE_LEVELS:
                return (
                    f"the time histories model {TIE_LEVELS_RULE}; this tie is a level {level + 1}",
                    ("ties", i),
                )
        return None
