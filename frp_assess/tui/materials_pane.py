"""The Materials tab: the FRP bar materials (the library and the project's own)."""

from __future__ import annotations

from typing import Any

from textual.app import ComposeResult
from textual.containers import Vertical
from textual.widgets import Static

from frp_assess.tui.materials import MaterialsEditor


class MaterialsPane(Vertical):
    """The ``materials`` block of the project: it holds the entries (in its editor), loads
    them from the project data and gives them back for it."""

    def compose(self) -> ComposeResult:
        yield Static("FRP bar materials (library and the project's)", classes="section-title")
        yield MaterialsEditor(id="materials-editor")

    @property
    def editor(self) -> MaterialsEditor:
        return self.query_one(MaterialsEditor)

    def load(self, data: dict[str, Any]) -> None:
        """Show the ``materials`` of the project data (as the YAML loader reads it)."""
        self.editor.load_entries(data.get("materials") or {})

    def data(self) -> dict[str, Any]:
        """The ``materials`` block as edited."""
        return self.editor.data()

    def refresh_view(self) -> None:
        """Redraw the table (the problems or the library shown may have changed)."""
        self.editor.refresh_table()
