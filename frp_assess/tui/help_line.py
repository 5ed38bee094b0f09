"""The help line: what the focused field means (its unit and range) or which keys work."""

from __future__ import annotations

from rich.text import Text
from textual.widget import Widget
from textual.widgets import DataTable, Static, Tabs

from frp_assess.tui.fields import FieldRow

#: the hint of a table, by id (others: the editors' tables)
TABLE_HINTS = {"ranking-table": "←/→ column · s sort · enter: per-record IDA of the case"}
EDITOR_TABLE_HINT = "↑/↓ select · a add · d duplicate · del remove · enter edit"


class HelpLine(Static):
    """One line above the status, following the focus."""

    def show_for(self, widget: Widget) -> None:
        """The help of the focused ``widget``."""
        row = next((a for a in widget.ancestors_with_self if isinstance(a, FieldRow)), None)
        if row is not None:
            self.update(Text(row.spec.help or row.spec.label, style="italic"))
        elif isinstance(widget, DataTable):
            self.update(Text(TABLE_HINTS.get(str(widget.id), EDITOR_TABLE_HINT), "italic"))
        elif isinstance(widget, Tabs):
            self.update(Text("←/→ switch tab · tab: into the tab · F2…F10: main tabs", "italic"))
        else:
            self.update(Text("tab: next field · ?/F1: help", style="italic dim"))
