"""The loads the wall carries (``wall.loads``, docs/model.md §12): three tables on the Wall
tab, the top loads, the thrusts and the ties, each with a form for the selected item.  Keys
while a table has focus: ``a`` add, ``d`` duplicate, ``delete``/``x`` remove.  The problems
are the project file's (the same validation, the same messages as ``validate``).
"""

from __future__ import annotations

from typing import Any, ClassVar

from frp_assess.config.messages import Loc
from frp_assess.config.schema.loads_spec import ThrustSpec, TieSpec, TopLoadSpec
from frp_assess.tui.core.editor_state import format_value
from frp_assess.tui.fields import choice, num, text
from frp_assess.tui.item_editor import ItemEditor

#: the key path of the block the three tables edit
LOADS: Loc = ("wall", "loads")


def _name(item: dict[str, Any], kind: str, index: int) -> str:
    return str(item.get("name") or f"{kind} {index + 1}")


class TopLoadsEditor(ItemEditor):
    """``wall.loads.top``: floors and roof bearing on the top of the wall."""

    ROOT = (*LOADS, "top")
    FORMS: ClassVar[dict[str, Any]] = {
        "top": (
            text(("name",), "Name", TopLoadSpec, optional=True, width=30),
            num(("load",), "Load P", "kN/m", TopLoadSpec),
            num(("distance",), "Distance d", "m from the outer face", TopLoadSpec),
            # blank: the schema's default (carried), the key left out as the file had it
            choice(
                ("inertia",),
                "Inertia",
                None,
                TopLoadSpec,
                optional=True,
                width=16,
                default=None,
                unit="blank: carried",
            ),  # fmt: skip
        )
    }

    def columns(self) -> list[str]:
        return ["#", "name", "P [kN/m]", "d [m]", "mass"]

    def row_cells(self, index: int, item: Any) -> list[Any]:
        return [index + 1, _name(item, "top load", index), format_value(item.get("load")),
                format_value(item.get("distance")), item.get("inertia") or "carried"]  # fmt: skip

    def new_item(self, action: str) -> Any:
        return {"load": 10.0, "distance": 0.0, "inertia": "carried"}


class ThrustsEditor(ItemEditor):
    """``wall.loads.thrust``: outward horizontal forces on the inner face."""

    ROOT = (*LOADS, "thrust")
    FORMS: ClassVar[dict[str, Any]] = {
        "thrust": (
            text(("name",), "Name", ThrustSpec, optional=True, width=30),
            num(("force",), "Force F", "kN/m, outward", ThrustSpec),
            num(("height",), "Height h", "m above the base", ThrustSpec),
        )
    }

    def columns(self) -> list[str]:
        return ["#", "name", "F [kN/m]", "h [m]"]

    def row_cells(self, index: int, item: Any) -> list[Any]:
        return [index + 1, _name(item, "thrust", index), format_value(item.get("force")),
                format_value(item.get("height"))]  # fmt: skip

    def new_item(self, action: str) -> Any:
        return {"force": 1.0, "height": 1.0}


#: the fields of a tie but its name (``wall.loads.ties`` and a tie option, ``type: tie``)
TIE_FIELDS = (
    num(("height",), "Height h_t", "m above the base", TieSpec),
    num(("diameter",), "Diameter", "mm (or area)", TieSpec, optional=True),
    num(("area",), "Area A_s", "mm2 (or diameter)", TieSpec, optional=True),
    num(("spacing",), "Spacing i_t", "m", TieSpec),
    num(("length",), "Length L_t", "m, free", TieSpec),
    num(("yield_strength",), "f_y", "MPa", TieSpec, optional=True),
    num(("elastic_modulus",), "E_s", "GPa", TieSpec, optional=True),
    num(("anchorage",), "Anchorage F_a", "kN per tie", TieSpec, optional=True,
        placeholder="(not governing)"),
)  # fmt: skip


class TiesEditor(ItemEditor):
    """``wall.loads.ties``: steel tie-rods anchored on the outer face."""

    ROOT = (*LOADS, "ties")
    FORMS: ClassVar[dict[str, Any]] = {
        "tie": (text(("name",), "Name", TieSpec, optional=True, width=30), *TIE_FIELDS)
    }

    def columns(self) -> list[str]:
        return ["#", "name", "h_t [m]", "Ø [mm]", "i_t [m]", "F_a [kN]"]

    def row_cells(self, index: int, item: Any) -> list[Any]:
        size = item.get("diameter")
        shown = format_value(size) if size is not None else f"A {format_value(item.get('area'))}"
        anchorage = format_value(item.get("anchorage")) or "—"
        return [index + 1, _name(item, "tie", index), format_value(item.get("height")), shown,
                format_value(item.get("spacing")), anchorage]  # fmt: skip

    def new_item(self, action: str) -> Any:
        return {"height": 1.0, "diameter": 20.0, "spacing": 3.0, "length": 6.0}


#: the three tables, in the order of the block's keys
LOAD_EDITORS: tuple[type[ItemEditor], ...] = (TopLoadsEditor, ThrustsEditor, TiesEditor)


def loads_data(lists: dict[str, list[Any]]) -> dict[str, Any] | None:
    """The ``wall.loads`` block of the three tables' items (every list, as the loader gives
    the block), None when all are empty (the key is then left out: a free-standing wall)."""
    return dict(lists) if any(lists.values()) else None
