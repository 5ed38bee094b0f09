"""The ``building`` block of a study file: walls above the ground floor, with the height of
their base as an axis (``wall_base``), to show how the improvement changes with it.

As the project file's ``building`` block (:class:`frp_assess.config.schema.BuildingSpec`,
docs/model.md §9), except that ``wall_base`` is a list of heights Z [m].
"""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from frp_assess.config.schema import Number, WholeNumber
from frp_assess.motions.floor import default_period


class StudyBuilding(BaseModel):
    """The building the walls of a study stand in, and the heights of their bases."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    # the ranges of a project's building block (config.schema.wall_spec.BuildingSpec)
    height: Number = Field(
        ge=2, le=200, description="H_b [m], height of the building above the foundation, 2-200"
    )
    storeys: WholeNumber = Field(ge=1, le=60, description="n, number of storeys, 1-60")
    wall_base: list[Number] = Field(
        min_length=1,
        description="axis: Z [m], heights of the wall's rocking base, each 0 <= Z < H_b",
    )
    period: Number | None = Field(
        None,
        ge=0.02,
        le=5,
        description="T1 [s] of the building, 0.02-5; default 0.05*H_b^0.75 (Circolare eq. C7.3.2)",
    )
    damping: Number = Field(
        0.05, ge=0.005, le=0.3, description="xi of the building's first mode [-], 0.005-0.3"
    )

    @field_validator("wall_base")
    @classmethod
    def _distinct(cls, v: list[float]) -> list[float]:
        if len(set(v)) != len(v):
            raise ValueError(f"wall_base: repeated values {v}")
        return v

    @model_validator(mode="after")
    def _below_the_top(self) -> StudyBuilding:
        for z in self.wall_base:
            if not 0.0 <= z < self.height:
                raise ValueError(
                    f"wall_base: expected 0 <= Z < height H_b = {self.height:g} m, found {z:g}"
                )
        return self

    @property
    def first_period(self) -> float:
        """T1 [s]: the given period, else 0.05·H_b^(3/4) (Circolare 2019 eq. C7.3.2)."""
        return float(self.period) if self.period is not None else default_period(self.height)
