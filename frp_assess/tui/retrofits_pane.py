"""The Retrofits tab: the options and sweeps, and the options they expand to."""

from __future__ import annotations

from typing import Any

from rich.table import Table
from rich.text import Text
from textual.app import ComposeResult
from textual.containers import Vertical
from textual.widgets import Static

from frp_assess.config.schema import Project
from frp_assess.tui.core.project_info import option_rows, retrofits_summary
from frp_assess.tui.interventions import InterventionsEditor
from frp_assess.tui.literal import literal


class RetrofitsPane(Vertical):
    """The ``interventions`` list of the project: it holds the items (in its editor), loads
    them from the project data, gives them back, and shows the options a run compares."""

    def compose(self) -> ComposeResult:
        yield Static("", id="retrofits-info", classes="section-title")
        yield InterventionsEditor(id="interventions-editor")
        yield Static("", id="expanded-options")

    def on_mount(self) -> None:
        self.shown: dict[str, Any] = {}

    @property
    def editor(self) -> InterventionsEditor:
        return self.query_one(InterventionsEditor)

    def load(self, data: dict[str, Any]) -> None:
        """Show the ``interventions`` of the project data (as the YAML loader reads it)."""
        items = data.get("interventions") or []
        self.editor.load(list(items) if isinstance(items, list) else [])

    def items(self) -> list[Any]:
        """The ``interventions`` list as edited."""
        return self.editor.items

    def show_project(
        self,
        project: Project | None,
        wall: Any,
        wall_data: Any,
        materials: dict[str, Any],
    ) -> None:
        """Update the table's FRP masses (``wall``: derived values or why not; ``materials``:
        the material table by name), the summary and the expanded options (valid only)."""
        editor = self.editor
        editor.context = {"wall": wall, "wall_data": wall_data, "materials": materials}
        editor.set_materials(list(materials))
        editor.refresh_table()
        self._update("#retrofits-info", retrofits_summary(project), literal)
        if project is None or isinstance(wall, str):
            self._update("#expanded-options", None, lambda _: "")
            return
        rows = option_rows(project)
        key = (tuple(rows), str(project.costs.currency), project.wall.length)
        self._update("#expanded-options", key, lambda k: options_table(*k))

    def _update(self, selector: str, key: Any, render: Any) -> None:
        if self.shown.get(selector, ()) != key:
            self.shown[selector] = key
            self.query_one(selector, Static).update(render(key))


def options_table(rows: tuple[Any, ...], currency: str, length: float) -> Table:
    """The options compared, with FRP mass per metre [kg/m], mass [kg] and cost (bars and
    ties); with a tie option, also each option's kind and tie steel per metre [kg/m]."""
    ties = any(r.kind != "bars" for r in rows)
    t = Table(
        title=Text(f"Options compared (wall length L = {length:g} m)", "bold"),
        title_justify="left",
        min_width=60,
        box=None,
        padding=(0, 2, 0, 0),
    )
    t.add_column(Text("option"))
    t.add_column(Text("FRP [kg/m]"), justify="right")
    t.add_column(Text("FRP [kg]"), justify="right")
    t.add_column(literal(f"cost [{currency}]"), justify="right")
    if ties:
        t.add_column(Text("kind"))
        t.add_column(Text("tie steel [kg/m]"), justify="right")
    for r in rows:
        extra = [r.kind, f"{r.steel_per_m:.2f}" if r.kind != "bars" else "—"] if ties else []
        t.add_row(literal(r.name), f"{r.mass_per_m:.2f}", f"{r.mass:.1f}", f"{r.cost:.0f}", *extra)
    return t
