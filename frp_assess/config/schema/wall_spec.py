"""The ``wall`` block (the rocking masonry wall) and the ``building`` block (where it
stands: its base moves with the floor).
"""

from __future__ import annotations

from pydantic import (
    Field,
    field_validator,
    model_validator,
)
from pydantic_core import PydanticCustomError

from frp_assess.config.library import MASONRY, did_you_mean
from frp_assess.config.schema.loads_spec import WallLoadsSpec
from frp_assess.config.schema.spec_base import (
    HEIGHT_RANGE,
    THICKNESS_RANGE,
    Number,
    WholeNumber,
    _Model,
    located_error,
)
from frp_assess.dynamics.wall import Mechanism
from frp_assess.motions.floor import default_period
from frp_assess.rules.geometry import slenderness_problem
from frp_assess.rules.wall_loads import Thrust, TopLoad, stabilising_moment


# ------------------------------------------------------------------------------------ wall
class WallSpec(_Model):
    """The masonry wall, a rigid rocking block (docs/model.md §1)."""

    thickness: Number = Field(  # the ranges' reasons: at THICKNESS_RANGE
        ge=THICKNESS_RANGE[0],
        le=THICKNESS_RANGE[1],
        description="Thickness B [m], 0.05 <= B <= 5, < height.",
    )
    height: Number = Field(
        ge=HEIGHT_RANGE[0],
        le=HEIGHT_RANGE[1],
        description="Height H [m] above the rocking base, 0.5 <= H <= 50.",
    )
    # below 0.1 m no bar fits: a length shorter than one bar spacing has no layout
    length: Number = Field(
        1.0,
        ge=0.1,
        le=1000,
        description="Length L [m] of the wall, for quantities and costs, 0.1 <= L <= 1000 "
        "(default 1).",
    )
    masonry: str | None = Field(
        None,
        description="Masonry type, a key of Circolare 2019 Tab. C8.5.I: "
        + ", ".join(f"{k} ({m.unit_weight:g} kN/m3)" for k, m in MASONRY.items())
        + ". Gives the unit weight unless unit_weight is given.",
    )
    unit_weight: Number | None = Field(
        None, ge=5.0, le=30.0, description="Unit weight w [kN/m3], 5-30; wins over masonry."
    )
    # the weakest masonry of Tab. C8.5.I has 1.0 MPa; below 0.1 MPa no wall carries itself
    compressive_strength: Number | None = Field(
        None,
        ge=0.1,
        le=100,
        description="Compressive strength f_m of the masonry [MPa], 0.1-100; wins over the "
        "masonry type's value of Tab. C8.5.I (LC1: minimum, LC2/LC3: mean).  Divided by FC of "
        "code_check.knowledge_level, it sizes the compressed zone at the pivot.",
    )
    mechanism: Mechanism = Field(
        description="one-sided: wall restrained on one side (rebounds on impact); "
        "two-sided: free-standing wall rocking both ways."
    )
    loads: WallLoadsSpec | None = Field(
        None,
        description="What bears on and pushes the wall: top loads (floors, roof), outward "
        "thrusts, steel tie-rods (docs/model.md §12); omit for a free-standing wall.",
    )

    @field_validator("masonry")
    @classmethod
    def _known_masonry(cls, value: str | None) -> str | None:
        if value is not None and value not in MASONRY:
            raise PydanticCustomError(
                "unknown_masonry",
                f"unknown masonry {value!r}{did_you_mean(value, MASONRY)}; "
                f"expected one of {', '.join(MASONRY)}",
            )
        return value

    @model_validator(mode="after")
    def _check_wall(self) -> WallSpec:
        if slenderness_problem(self.thickness, self.height) is not None:
            raise located_error(
                f"expected thickness B < height H = {self.height:g} m, found {self.thickness:g}"
                " (a rocking wall is slender)",
                "thickness",
            )
        if self.masonry is None and self.unit_weight is None:
            raise located_error(
                "give 'masonry' (a library key) or 'unit_weight' [kN/m3]; neither was found"
            )
        if self.loads is not None:
            self._check_loads(self.loads)
        return self

    def _check_loads(self, loads: WallLoadsSpec) -> None:
        """Loads outside the wall, more tie levels than the time histories hold, and thrusts
        that tip it without an earthquake, refused."""
        if (problem := loads.problem(self.thickness, self.height)) is not None:
            message, where = problem
            raise located_error(message, "loads", *where)
        if loads.thrust:
            self._check_thrusts(loads)

    def _check_thrusts(self, loads: WallLoadsSpec) -> None:
        """Thrusts that tip the wall without an earthquake, refused."""
        weight = self.unit_weight_kn * self.thickness * self.height  # [kN/m]
        top = [TopLoad(p.load, p.distance, p.inertia == "carried") for p in loads.top]
        thrusts = [Thrust(f.force, f.height) for f in loads.thrust]
        hold = stabilising_moment(weight, self.thickness, self.height, top, [], 1)
        push = sum(f.force * f.height for f in thrusts)
        if push >= hold:
            raise located_error(
                f"expected thrusts the wall stands against at rest, found sum(F*h) = {push:.4g} "
                f"kNm/m against W*B/2 + sum(P*d) = {hold:.4g} kNm/m about the outer corner "
                "(the wall tips without an earthquake)",
                "loads",
                "thrust",
            )

    @property
    def unit_weight_kn(self) -> float:
        """Unit weight w [kN/m³]: the explicit value, else the masonry library's."""
        if self.unit_weight is not None:
            return float(self.unit_weight)
        assert self.masonry is not None
        return MASONRY[self.masonry].unit_weight


# -------------------------------------------------------------------------------- building
class BuildingSpec(_Model):
    """Where the wall stands in the building: its base moves with the floor at Z
    (first mode only, Circolare 2019 §C7.2.3; docs/model.md §9)."""

    # one storey is at least 2 m high
    height: Number = Field(
        ge=2,
        le=200,
        description="H_b [m], height of the building above the foundation, 2-200.",
    )
    storeys: WholeNumber = Field(ge=1, le=60, description="n, number of storeys, 1-60.")
    wall_base: Number = Field(
        ge=0,
        description="Z [m], height of the wall's rocking base above the foundation, 0 <= Z < H_b.",
    )
    # below 0.02 s the floor moves as the ground (the default for H_b = 2 m is 0.08 s)
    period: Number | None = Field(
        None,
        ge=0.02,
        le=5,
        description="T1 [s], fundamental period of the building, 0.02-5; default "
        "0.05*H_b^0.75 (Circolare 2019 eq. C7.3.2, masonry).",
    )
    # below 0.5 % no building is damped (steel frames have about 2 %)
    damping: Number = Field(
        0.05,
        ge=0.005,
        le=0.3,
        description="xi of the building's first mode [-], 0.005-0.3 (0.05).",
    )

    @model_validator(mode="after")
    def _check_base(self) -> BuildingSpec:
        if self.wall_base >= self.height:
            raise located_error(
                f"expected 0 <= Z < height H_b = {self.height:g} m, found {self.wall_base:g}",
                "wall_base",
            )
        return self

    @property
    def first_period(self) -> float:
        """T1 [s]: the given period, else C1·H_b^(3/4) with C1 = 0.050 (eq. C7.3.2)."""
        if self.period is not None:
            return float(self.period)
        return default_period(float(self.height))
