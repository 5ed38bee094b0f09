"""The retrofit options (``interventions:``): single options and sweeps in one table.

Each row shows the FRP mass per metre of wall of the option (for a sweep, its range), which
updates as the wall, the materials or the ratio are typed; a tie option (``type: tie``,
docs/model.md §12) shows its tie.  Keys: ``a`` add an option, ``s`` add a sweep, ``t`` add a
tie, ``d`` duplicate, ``delete``/``x`` remove.
"""

from __future__ import annotations

from typing import Any, ClassVar

from rich.text import Text
from textual.binding import Binding, BindingType

from frp_assess.config.library import FRP_MATERIALS
from frp_assess.config.schema import Intervention, SweepAxes, TieOption, option_name, tie_label
from frp_assess.tui.core.editor_state import expand_item, format_value, frp_mass_per_m
from frp_assess.tui.fields import choice, items, num, text
from frp_assess.tui.item_editor import ItemEditor
from frp_assess.tui.loads_editors import TIE_FIELDS


class InterventionsEditor(ItemEditor):
    """The ``interventions`` list: options and sweeps."""

    inherit_bindings = False
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("a", "add", "Add"),
        Binding("s", "add_sweep", "Sweep"),
        Binding("t", "add_tie", "Tie"),
        Binding("d", "duplicate", "Dup"),
        Binding("delete,x", "remove", "Remove", key_display="del"),
    ]
    BUTTONS = (
        ("+ option", "add"),
        ("+ sweep", "add_sweep"),
        ("+ tie", "add_tie"),
        ("duplicate", "duplicate"),
        ("remove", "remove"),
    )
    ROOT = ("interventions",)
    FORMS: ClassVar[dict[str, Any]] = {
        "option": (
            text(
                ("name",), "Name", Intervention, optional=True, width=30, placeholder="(generated)"
            ),
            choice(("material",), "Material", tuple(FRP_MATERIALS), Intervention, width=22),
            choice(("position",), "Position", None, Intervention, width=14),
            num(("ratio",), "Ratio ρ", "‰, 0 < ρ ≤ 20", Intervention),
            num(
                ("diameter",),
                "Bar Ø",
                "mm, catalogue",
                Intervention,
                optional=True,
                placeholder="(least ρ)",
            ),
        ),
        "sweep": (
            items(("sweep", "material"), "Materials", SweepAxes, width=30, unit="comma-separated"),
            items(
                ("sweep", "position"), "Positions", SweepAxes, width=30, unit="centred, external"
            ),
            items(("sweep", "ratio"), "Ratios ρ", SweepAxes, width=30, unit="‰, e.g. 1, 2, 3"),
        ),
        "tie": (
            text(("name",), "Name", TieOption, optional=True, width=30, placeholder="(generated)"),
            *TIE_FIELDS,
        ),
    }

    def columns(self) -> list[str]:
        return ["#", "kind", "name", "material", "position", "ρ [‰]", "options", "FRP [kg/m]"]

    def kind_of(self, item: Any) -> str:
        if isinstance(item, dict) and "sweep" in item:
            return "sweep"
        return "tie" if isinstance(item, dict) and "type" in item else "option"

    def item_label(self, index: int) -> str:
        return f"#{index + 1} {self.kind_of(self.items[index])}"

    def new_item(self, action: str) -> Any:
        if action == "sweep":
            return {
                "sweep": {"material": ["GFRP"], "position": ["centred", "external"], "ratio": [1.0]}
            }
        if action == "tie":
            return {"type": "tie", "height": 3.0, "diameter": 20.0, "spacing": 3.0, "length": 8.0}
        return {"material": "GFRP", "position": "external", "ratio": 1.0}

    def _append(self, action: str) -> None:
        self.items.append(self.new_item(action))
        self.refresh_table()
        self.table.move_cursor(row=len(self.items) - 1)
        self.changed()

    def action_add_sweep(self) -> None:
        self._append("sweep")

    def action_add_tie(self) -> None:
        self._append("tie")

    def set_materials(self, names: list[str]) -> None:
        """Offer these material names in the option form."""
        for row in self.form_rows("option"):
            if row.spec.path == ("material",):
                row.set_choices([(n, n) for n in names])

    def _mass(self, material: str, position: str, ratio: Any) -> float | None:
        ctx = self.context
        return frp_mass_per_m(
            ctx.get("wall"),  # type: ignore[arg-type]
            ctx.get("wall_data"),
            ctx.get("materials", {}).get(material),
            position,
            ratio,
        )

    def _tie_cells(self, index: int, item: Any) -> list[Any]:
        name = item.get("name")
        if not name:
            try:
                name = Text(tie_label(TieOption.model_validate(item)), style="dim")
            except ValueError:  # pydantic's ValidationError: an incomplete tie
                name = ""
        return [index + 1, Text("tie", style="cyan"), name, "—", "—", "—", 1, "—"]

    def row_cells(self, index: int, item: Any) -> list[Any]:
        if self.kind_of(item) == "tie":
            return self._tie_cells(index, item)
        combos = expand_item(item)
        masses = [self._mass(m, p, r) for m, p, r in combos]
        known = [m for m in masses if m is not None]
        if not known:
            mass = "—"
        elif len(known) == 1:
            mass = f"{known[0]:.2f}"
        else:
            mass = f"{min(known):.2f}–{max(known):.2f}"
        if self.kind_of(item) == "sweep":
            ax = item.get("sweep") if isinstance(item.get("sweep"), dict) else {}
            return [
                index + 1,
                Text("sweep", style="magenta"),
                "",
                format_value(ax.get("material")),
                format_value(ax.get("position")),
                format_value(ax.get("ratio")),
                len(combos),
                mass,
            ]
        name = item.get("name")
        if not name:
            try:
                name = Text(
                    option_name(str(item["material"]), str(item["position"]), item["ratio"]),
                    style="dim",
                )
            except (KeyError, TypeError, ValueError):
                name = ""
        return [
            index + 1,
            "option + tie" if isinstance(item.get("tie"), dict) else "option",
            name,
            format_value(item.get("material")),
            format_value(item.get("position")),
            format_value(item.get("ratio")),
            1,
            mass,
        ]
