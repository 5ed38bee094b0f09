"""FRP bar materials: the library with the project's overrides and new materials.

The table lists every material the options can use.  For a library material an empty field
keeps the library value (shown greyed as the placeholder); a new material needs all four
numbers.  Keys: ``a`` add a material (named in the field below the table), ``delete``/``x``
remove the project's entry (for a library material: back to the library values).
"""

from __future__ import annotations

from typing import Any, ClassVar

from rich.text import Text
from textual import on
from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Horizontal
from textual.widgets import Button, Input, Label

from frp_assess.config.library import FRP_MATERIALS
from frp_assess.config.messages import Loc
from frp_assess.config.schema import FrpMaterialSpec
from frp_assess.tui.core.editor_state import MISSING, format_value, get_path, set_path
from frp_assess.tui.fields import OrderedInput, choice, num, text
from frp_assess.tui.item_editor import ItemEditor

MATERIAL_FIELDS = tuple(FrpMaterialSpec.model_fields)


class MaterialsEditor(ItemEditor):
    """The ``materials`` mapping, shown with the library."""

    inherit_bindings = False
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("a", "add", "Add"),
        Binding("delete,x", "remove", "Remove/reset", key_display="del"),
    ]
    BUTTONS = (("+ add", "add"), ("remove / reset", "remove"))
    ROOT = ("materials",)
    FORMS: ClassVar[dict[str, Any]] = {
        "material": (
            num(("elastic_modulus",), "E", "GPa", FrpMaterialSpec, width=20),
            num(("ultimate_strain",), "ε_u", "-", FrpMaterialSpec, width=20),
            num(("density",), "Density", "kg/m³", FrpMaterialSpec, width=20),
            num(("price",), "Price", "currency/kg", FrpMaterialSpec, width=20),
            text(("source",), "Source", FrpMaterialSpec, optional=True, width=40),
            num(
                ("characteristic_strain",),
                "ε_fk",
                "-, 5 % fractile",
                FrpMaterialSpec,
                optional=True,
                width=20,
                placeholder="(from ε_u)",
            ),
            choice(("fibre",), "Fibre", None, FrpMaterialSpec, optional=True, width=20),
        )
    }

    def __init__(self, *, id: str | None = None) -> None:
        super().__init__(id=id)
        #: name -> the project's entry (a dict of given fields); library names too
        self.entries: dict[str, dict[str, Any]] = {}

    def compose(self) -> ComposeResult:
        yield from super().compose()
        with Horizontal(classes="mat-new"):
            yield Label("New material name ", classes="f-label")
            yield OrderedInput(compact=True, id="mat-new-name", placeholder="e.g. AFRP")
            yield Button("add", compact=True, id="mat-new-add")

    # items are the names, in table order: the library first, then the project's own
    def load_entries(self, entries: Any) -> None:
        """Replace the project's materials (a file was opened)."""
        self.entries = {
            str(k): dict(v) if isinstance(v, dict) else v
            for k, v in (entries.items() if isinstance(entries, dict) else [])
        }
        self.load(self._names())

    def _names(self) -> list[str]:
        return list(dict.fromkeys([*FRP_MATERIALS, *self.entries]))

    def data(self) -> dict[str, Any]:
        """The ``materials`` block: entries with at least one field, and new materials."""
        return {
            k: v
            for k, v in self.entries.items()
            if k not in FRP_MATERIALS or not isinstance(v, dict) or v
        }

    def item_path(self, index: int) -> Loc:
        return ("materials", self.items[index])

    def item_label(self, index: int) -> str:
        name = self.items[index]
        origin = "library" if name in FRP_MATERIALS else "project material"
        if name in FRP_MATERIALS and self.entries.get(name):
            origin = "library, with overrides"
        return (
            f"{name} ({origin}; empty fields keep the library value)"
            if (name in FRP_MATERIALS)
            else f"{name} ({origin}; needs E, ε_u, density and price)"
        )

    def columns(self) -> list[str]:
        return ["material", "E [GPa]", "ε_u", "ρ [kg/m³]", "price", "origin", "source"]

    def row_cells(self, index: int, item: Any) -> list[Any]:
        name = item
        entry = self.entries.get(name) or {}
        lib = FRP_MATERIALS.get(name)
        cells: list[Any] = [name]
        for f in ("elastic_modulus", "ultimate_strain", "density", "price"):
            if isinstance(entry, dict) and f in entry:
                cells.append(Text(format_value(entry[f]), style="bold"))
            elif lib is not None:
                cells.append(Text(format_value(getattr(lib, f)), style="dim"))
            else:
                cells.append(Text("?", style="red"))
        if lib is None:
            origin = "project"
        elif entry:
            origin = "overridden"
        else:
            origin = "library"
        source = (entry.get("source") if isinstance(entry, dict) else None) or (
            lib.source if lib else ""
        )
        source = str(source)
        if len(source) > 40:  # the whole text is in the form below the table
            source = source[:39] + "…"
        cells += [origin, Text(source, style="dim")]
        return cells

    def item_value(self, index: int, path: Loc) -> Any:
        entry = self.entries.get(self.items[index])
        return get_path(entry, path) if isinstance(entry, dict) else MISSING

    def form_filled(self, index: int) -> None:
        lib = FRP_MATERIALS.get(self.items[index])
        for row in self.form_rows("material"):
            if row.spec.kind != "choice":
                value = None if lib is None else getattr(lib, str(row.spec.path[0]))
                row.set_placeholder(
                    row.spec.placeholder if value is None else f"{format_value(value)} (library)"
                )

    def apply_field(self, index: int, path: Loc, value: Any) -> None:
        name = self.items[index]
        entry = self.entries.setdefault(name, {})
        if isinstance(entry, dict):
            set_path(entry, path, value)

    def new_item(self, action: str) -> Any:  # pragma: no cover - adding goes by name
        raise NotImplementedError

    def action_add(self) -> None:
        self.query_one("#mat-new-name", Input).focus()

    @on(Input.Submitted, "#mat-new-name")
    @on(Button.Pressed, "#mat-new-add")
    def _add_named(self, event: Input.Submitted | Button.Pressed) -> None:
        event.stop()
        box = self.query_one("#mat-new-name", Input)
        name = box.value.strip()
        if not name:
            self.app.notify("type the new material's name first", severity="warning", markup=False)
            box.focus()
            return
        if name in self.items:
            self.app.notify(f"{name} is already in the table", severity="warning", markup=False)
        else:
            self.entries[name] = {}
            self.items = self._names()
        box.value = ""
        self.refresh_table()
        self.table.move_cursor(row=self.items.index(name))
        self.changed()
        self.form_rows("material")[0].control.focus()

    def action_duplicate(self) -> None:  # materials are named: add a new one instead
        self.action_add()

    def action_remove(self) -> None:
        i = self.selected
        if i is None:
            return
        name = self.items[i]
        self.entries.pop(name, None)
        self.items = self._names()
        self.refresh_table()
        self.changed()
