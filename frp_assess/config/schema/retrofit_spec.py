"""The retrofit blocks: ``materials`` (FRP bar materials), ``bars`` (the bars as built),
``interventions`` (options and sweeps) and ``design`` (the smallest ratio meeting the
target).
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

from pydantic import (
    Discriminator,
    Field,
    Tag,
    model_validator,
)

from frp_assess.config.schema.loads_spec import TieSpec
from frp_assess.config.schema.spec_base import (
    MAX_BAR_AREA,
    MAX_BAR_DIAMETER,
    MAX_NAME_CHARS,
    MIN_BAR_DIAMETER,
    MIN_RATIO,
    MIN_SPACING,
    MODULUS_RANGE,
    STRAIN_RANGE,
    Exposure,
    Fibre,
    FreeText,
    Number,
    _Model,
    located_error,
)
from frp_assess.dynamics.rebars import POSITIONS, Position
from frp_assess.rules.bars import DEFAULT_STRAIN_COV, FRACTILE_5_PERCENT, MAX_RATIO


# ------------------------------------------------------------------------------ materials
class FrpMaterialSpec(_Model):
    """An FRP bar material added to, or overriding fields of, the library (GFRP, BFRP, CFRP).

    For a library material only the fields given are replaced; a new material needs
    elastic_modulus, ultimate_strain, density and price.
    """

    # FRP bars: E 30-250 GPa, eps_u 0.005-0.035, density 1400-2600 kg/m3; the ranges are
    # what any bar material can be (see MODULUS_RANGE; no bar is lighter than 100 kg/m3)
    elastic_modulus: Number | None = Field(
        None, ge=MODULUS_RANGE[0], le=MODULUS_RANGE[1], description="E [GPa], 1-1000."
    )
    ultimate_strain: Number | None = Field(
        None, ge=STRAIN_RANGE[0], le=STRAIN_RANGE[1], description="eps_u [-], 0.0001-0.1."
    )
    density: Number | None = Field(
        None, ge=100, le=10000, description="Density [kg/m3], 100-10000."
    )
    price: Number | None = Field(
        None, ge=0, le=1e6, description="Indicative price [currency/kg], 0-1e6."
    )
    source: FreeText | None = Field(
        None,
        max_length=MAX_NAME_CHARS,
        description=f"Source of the values (text, at most {MAX_NAME_CHARS} characters).",
    )
    characteristic_strain: Number | None = Field(
        None,
        ge=STRAIN_RANGE[0],
        le=STRAIN_RANGE[1],
        description="Characteristic rupture strain eps_fk [-] (5 % fractile, producer's data "
        f"sheet); default eps_u*(1 - {FRACTILE_5_PERCENT:g}*{DEFAULT_STRAIN_COV:.2f}) "
        "(docs/model.md §2.1).",
    )
    fibre: Fibre | None = Field(
        None,
        description="Fibre for the environmental factor eta_a (CNR-DT 200 R1/2013 Table 3.2): "
        "glass | carbon | aramid | basalt (default: by the library key, glass for a new "
        "material).",
    )


# ------------------------------------------------------------------------------------ bars
class BarSizeSpec(_Model):
    """A bar size added to the built-in catalogue (nominal diameters 6-16 mm, area pi*d^2/4)."""

    material: str = Field(description="Material: a library key or one of 'materials'.")
    # no bar is thinner than 1 mm (the catalogue starts at 6 mm)
    diameter: Number = Field(
        ge=MIN_BAR_DIAMETER,
        le=MAX_BAR_DIAMETER,
        description=f"Nominal diameter d [mm], {MIN_BAR_DIAMETER:g}-{MAX_BAR_DIAMETER:g}.",
    )
    area: Number = Field(
        ge=0.5,
        le=MAX_BAR_AREA,
        description=f"Nominal area [mm2] (the producer's data sheet), 0.5-{MAX_BAR_AREA:g}.",
    )
    source: FreeText = Field(
        "user input",
        max_length=MAX_NAME_CHARS,
        description=f"Source (text, at most {MAX_NAME_CHARS} characters).",
    )


class AnchorageSpec(_Model):
    """Bond of the bars in resin-filled holes, for the anchorage length and the pull-out cone."""

    # a bond below 0.01 MPa anchors nothing (lengths of kilometres); the resin needs a
    # clearance of at least 0.1 mm around the bar
    hole_clearance: Number = Field(
        ge=0.1,
        le=50,
        description="Hole diameter minus bar diameter [mm] (d_h = d + clearance), 0.1-50.",
    )
    bond_bar: Number = Field(
        ge=0.01, le=50, description="Bond strength bar-resin tau_b [MPa] (producer's tests)."
    )
    bond_masonry: Number = Field(
        ge=0.01, le=10, description="Bond strength resin-masonry tau_m [MPa] (pull-out tests)."
    )
    tensile_strength: Number | None = Field(
        None,
        ge=0.001,
        le=10,
        description="Tensile strength f_t of the masonry for the pull-out cone [MPa] "
        "(default 1.5*tau_0d of wall.masonry and the knowledge level).",
    )


class BarsSpec(_Model):
    """The bars as they are built: catalogue, spacing rule, exposure, design values."""

    exposure: Exposure = Field(
        "external",
        description="Exposure of the bars (CNR-DT 200 R1/2013 Table 3.2): internal | external "
        "| aggressive (external).",
    )
    design_values: bool = Field(
        True,
        description="Use the design rupture strain c*eta_a*eps_fk/gamma_f (true); false: "
        "c*eps_u, the mean producer value (the paper).",
    )
    whole_bars: bool = Field(
        True,
        description="The model uses the ratio installed by whole bars (true); false: the "
        "ratio asked, smeared (the paper).",
    )
    min_spacing: Number = Field(
        0.10,
        ge=MIN_SPACING,
        le=10,
        description=f"Smallest spacing between bar axes [m], {MIN_SPACING:g}-10 (0.10).",
    )
    max_spacing: Number = Field(
        1.0,
        ge=MIN_SPACING,
        le=10,
        description=f"Largest spacing between bar axes [m], {MIN_SPACING:g}-10 (1.0).",
    )
    catalogue: list[BarSizeSpec] = Field(
        default_factory=list,
        max_length=200,
        description="Bar sizes added to (same diameter: replacing) the built-in nominal "
        "diameters 6-16 mm.",
    )
    anchorage: AnchorageSpec | None = Field(
        None, description="Bond strengths for the anchorage length and pull-out cone."
    )

    @model_validator(mode="after")
    def _spacing(self) -> BarsSpec:
        if self.min_spacing > self.max_spacing:
            raise located_error(
                f"expected min_spacing <= max_spacing = {self.max_spacing:g} m, found "
                f"{self.min_spacing:g}",
                "min_spacing",
            )
        seen: dict[tuple[str, float], int] = {}
        for i, size in enumerate(self.catalogue):
            j = seen.setdefault((size.material, float(size.diameter)), i)
            if j != i:
                raise located_error(
                    f"{size.material} Ø{size.diameter:g} is already catalogue[{j}]",
                    "catalogue",
                    i,
                    "diameter",
                )
        return self


# -------------------------------------------------------------------------- interventions
Ratio = Annotated[Number, Field(ge=MIN_RATIO, le=MAX_RATIO)]


class Intervention(_Model):
    """One retrofit option: vertical FRP bars of a material, position and ratio."""

    name: FreeText | None = Field(
        None,
        max_length=MAX_NAME_CHARS,
        description="Name in the results (default e.g. 'GFRP external 1‰'), at most "
        f"{MAX_NAME_CHARS} characters.",
    )
    material: str = Field(description="Material: a library key or one of 'materials'.")
    position: Position = Field(description="centred (one bar) | external (one on each face).")
    ratio: Ratio = Field(
        description=f"Ratio rho [per mille] of the active bars, {MIN_RATIO:g}-{MAX_RATIO:g}."
    )
    diameter: Number | None = Field(
        None,
        ge=MIN_BAR_DIAMETER,
        le=MAX_BAR_DIAMETER,
        description="Bar diameter d [mm], from the catalogue (default: the size installing "
        "the least ratio within the spacing rule).",
    )
    tie: TieSpec | None = Field(
        None,
        description="Steel tie-rods added with the bars (bars and a tie together; the fields of "
        "wall.loads.ties, docs/model.md §12); omit for bars alone.",
    )


class TieOption(TieSpec):
    """One retrofit option: steel tie-rods at one height, anchored on the outer face (the
    fields of ``wall.loads.ties``, docs/model.md §12); the option's wall is the wall with the
    tie added to its loads."""

    type: Literal["tie"] = Field(
        description="tie: steel tie-rods (an option without type is FRP bars)."
    )
    name: str = Field(
        "",
        max_length=MAX_NAME_CHARS,
        description="Name in the results (default e.g. 'Tie Ø20 @ 3.0 m at 6.0 m'), at most "
        f"{MAX_NAME_CHARS} characters.",
    )


def tie_label(tie: TieSpec) -> str:
    """A tie's generated name, e.g. ``Tie Ø20 @ 3.0 m at 6.0 m``: its bar (diameter, else
    area), its spacing along the wall and its height."""
    size = f"Ø{tie.diameter:g}" if tie.diameter is not None else f"A {tie.area_mm2:g} mm²"
    return f"Tie {size} @ {float(tie.spacing):.1f} m at {float(tie.height):.1f} m"


class SweepAxes(_Model):
    """Every combination of the listed materials, positions and ratios."""

    material: list[str] = Field(min_length=1, description="Materials (library or 'materials').")
    position: list[Position] = Field(min_length=1, description="Positions: centred, external.")
    ratio: list[Ratio] = Field(
        min_length=1, description=f"Ratios [per mille], {MIN_RATIO:g}-{MAX_RATIO:g}."
    )


class Sweep(_Model):
    """A sweep: expands into one option per combination."""

    sweep: SweepAxes = Field(description="The axes of the sweep.")


def _intervention_tag(value: Any) -> str:
    """``sweep-item`` (a ``sweep:`` key), ``tie-option`` (a ``type:`` key: only ``tie`` is
    valid, and the tie model says so) or ``option`` (FRP bars, the items without ``type``)."""
    if isinstance(value, dict):
        if "sweep" in value:
            return "sweep-item"
        return "tie-option" if "type" in value else "option"
    if isinstance(value, Sweep):
        return "sweep-item"
    return "tie-option" if isinstance(value, TieOption) else "option"


InterventionItem = Annotated[
    Annotated[Intervention, Tag("option")]
    | Annotated[TieOption, Tag("tie-option")]
    | Annotated[Sweep, Tag("sweep-item")],
    Discriminator(_intervention_tag),
]


# ---------------------------------------------------------------------- design/code/costs
class DesignSpec(_Model):
    """Design mode: the smallest ratio meeting the target per material and position."""

    materials: list[str] = Field(min_length=1, description="Materials to design with.")
    positions: list[Position] = Field(
        default_factory=lambda: list(POSITIONS),
        min_length=1,
        description="Positions (both by default).",
    )
    ratio_range: tuple[Ratio, Ratio] = Field(
        (0.5, 5.0),
        description=f"Search range [per mille], {MIN_RATIO:g} <= low < high <= {MAX_RATIO:g}.",
    )
    resolution: Number = Field(
        0.05, ge=0.001, le=1, description="Resolution [per mille], 0.001-1 (0.05)."
    )

    @model_validator(mode="after")
    def _range(self) -> DesignSpec:
        lo, hi = self.ratio_range
        if not lo < hi:
            raise located_error(f"expected low < high, found [{lo:g}, {hi:g}]", "ratio_range")
        res = self.resolution  # the search runs on the multiples of the resolution
        if math.floor(hi / res + 1e-9) < math.ceil(lo / res - 1e-9):
            raise located_error(
                f"expected a range holding a multiple of the resolution {res:g} ‰, found "
                f"[{lo:g}, {hi:g}]",
                "ratio_range",
            )
        return self
