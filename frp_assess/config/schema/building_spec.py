"""The JSON Schema's view of a building file (``walls:``, :mod:`frp_assess.config.walls_file`).

A building file is validated wall by wall as one-wall :class:`Project` files (so that every
check is the one-wall project's); these models only describe it, for ``frp-assess schema``
(editor completion): a wall of ``walls:`` is a :class:`WallSpec` with a name and, optionally,
its own ``building``, ``interventions`` and ``design``; the root holds ``wall`` or ``walls``.
"""

from __future__ import annotations

from pydantic import Field

from frp_assess.config.schema.project_spec import Project
from frp_assess.config.schema.retrofit_spec import DesignSpec, InterventionItem
from frp_assess.config.schema.spec_base import MAX_OPTIONS, FreeText
from frp_assess.config.schema.wall_spec import BuildingSpec, WallSpec

#: longest name of a wall of a building [characters] (as frp_assess.config.walls_file)
MAX_WALL_NAME = 80
#: most walls in one building file (as frp_assess.config.walls_file)
MAX_WALLS = 60


class WallItemSpec(WallSpec):
    """A wall of a building file: the keys of ``wall:`` with a name and its own blocks."""

    name: FreeText = Field(
        min_length=1,
        max_length=MAX_WALL_NAME,
        description=f"The wall's name, unique in the building (text, at most {MAX_WALL_NAME} "
        "characters); its results go to walls/<name>/.",
    )
    building: BuildingSpec | None = Field(
        None, description="Where this wall stands in the building (optional: at ground level)."
    )
    interventions: list[InterventionItem] | None = Field(
        None,
        max_length=MAX_OPTIONS,
        description="This wall's retrofit options (optional: the file's interventions).",
    )
    design: DesignSpec | None = Field(
        None, description="This wall's design mode (optional: the file's design)."
    )


class ProjectFileSchema(Project):
    """A project file: one wall (``wall:``) or a building's walls (``walls:``)."""

    wall: WallSpec | None = Field(  # type: ignore[assignment]
        None, description="The wall (a one-wall project; or walls:, exactly one of them)."
    )
    walls: list[WallItemSpec] | None = Field(
        None,
        min_length=1,
        max_length=MAX_WALLS,
        description="A building: several walls (local mechanisms) sharing the other blocks "
        "(instead of wall:); each is assessed as a one-wall project.",
    )
