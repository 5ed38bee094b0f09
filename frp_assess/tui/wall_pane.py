"""The Wall tab: project information, the wall and its derived constants."""

from __future__ import annotations

from typing import Any

from rich.table import Table
from rich.text import Text
from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.widgets import Static

from frp_assess.tui.core.editor_state import WallDerived
from frp_assess.tui.field_specs import (
    BUILDING_FIELDS,
    BUILDING_MODE,
    PROJECT_FIELDS,
    WALL_FIELDS,
)
from frp_assess.tui.fields import FieldRow, section_error
from frp_assess.tui.loads_editors import LOAD_EDITORS


class WallPane(VerticalScroll):
    """Project information, the wall and its derived constants."""

    def compose(self) -> ComposeResult:
        with Horizontal(classes="columns"):
            with Vertical(classes="col-left"):
                yield Static("Project", classes="section-title")
                for spec in PROJECT_FIELDS:
                    yield FieldRow(spec)
                yield Static("Wall (rigid rocking block)", classes="section-title")
                yield section_error("err-wall")
                for spec in WALL_FIELDS:
                    yield FieldRow(spec)
                yield Static("Loads on the wall (floors, roof, thrusts, ties; kN/m per metre "
                             "of wall)", classes="section-title")  # fmt: skip
                for editor in LOAD_EDITORS:
                    yield editor(id=f"loads-{editor.ROOT[-1]}-editor")
                yield Static("Building (a wall above the ground floor)", classes="section-title")
                yield FieldRow(BUILDING_MODE)
                with Vertical(classes="variant", id="var-building-on"):
                    for spec in BUILDING_FIELDS:
                        yield FieldRow(spec)
            with Vertical(classes="col-right"):
                yield Static("", id="derived-wall", classes="derived")

    def on_mount(self) -> None:
        self.shown: Any = None

    def show_derived(
        self, wall: WallDerived | str, pga_g: float | None, n_options: int | None
    ) -> None:
        """Show the derived constants (redrawn only when they change: typing stays cheap).

        ``wall``: the derived values or why they cannot be computed; ``pga_g``: a_g·S [g]
        of the spectrum (None: not known); ``n_options``: retrofit options (None: invalid).
        """
        key = (wall, pga_g, n_options)
        if key != self.shown:
            self.shown = key
            self.query_one("#derived-wall", Static).update(
                derived_wall_table(wall, pga_g, n_options)
            )


def derived_wall_table(
    wall: WallDerived | str, pga_g: float | None, n_options: int | None
) -> Table | Text:
    """The derived constants as a small table (or the reason they cannot be computed)."""
    if isinstance(wall, str):
        return Text.assemble(("Derived values\n", "bold"), (f"— {wall}", "red"))
    t = Table(
        title="Derived (as you type)",
        title_justify="left",
        box=None,
        show_header=False,
        padding=(0, 1, 0, 0),
    )
    t.add_column(style="bold cyan", no_wrap=True)
    t.add_column(justify="right", no_wrap=True)
    t.add_column(style="dim", no_wrap=True, overflow="ellipsis")
    t.add_row("α", f"{wall.alpha_deg:.3f}°", f"{wall.alpha:.4f} rad")
    t.add_row("R", f"{wall.R:.3f} m", "half diagonal")
    t.add_row("p", f"{wall.p:.3f} rad/s", "frequency")
    if wall.pivot == "crushing":
        t.add_row("x_W", f"{wall.depth * 1e3:.0f} mm", "W on 0.85·f_d")
        t.add_row("a_RM", f"{wall.a_rm:.4f} g", "g·(B − x_W)/H")
    else:
        t.add_row("a_RM", f"{wall.a_rm:.4f} g", "g·tan α")
    t.add_row("mass", f"{wall.mass:.0f} kg/m", "per metre")
    t.add_row("w", f"{wall.unit_weight:g} kN/m³", "unit weight")
    if pga_g is not None:
        t.add_row("a_g·S", f"{pga_g:.4f} g", "demand")
        ratio = wall.a_rm / pga_g
        t.add_row("a_RM/a_g·S", f"{ratio:.3f}", "no rocking" if ratio > 1 else "rocks")
    if n_options is not None:
        t.add_row("options", str(n_options), "retrofits")
    return t
