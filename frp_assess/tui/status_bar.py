"""The status line: the file, whether it is modified, the first problem, a run going on."""

from __future__ import annotations

from pathlib import Path

from rich.text import Text
from textual.widgets import Static

from frp_assess.tui.core.editor_state import Problem
from frp_assess.tui.core.tabs import tab_of, tab_title
from frp_assess.tui.literal import safe


class StatusBar(Static):
    """One line under the tabs, redrawn only when what it says changes."""

    def on_mount(self) -> None:
        self.shown = ""

    def show_state(
        self, path: Path | None, modified: bool, problems: list[Problem], running: bool
    ) -> None:
        where = path.name if path else "new project (not saved)"
        t = Text(f" {where}", style="bold")
        if path is not None and modified:
            t.append("  ● modified", "yellow")
        t.append("  │ ")
        if not problems:
            t.append("✓ valid", "green")
        else:
            p = problems[0]
            more = f" (+{len(problems) - 1} more)" if len(problems) > 1 else ""
            t.append(f"✗ {p}{more} [{tab_title(tab_of(p.target))}]", "red")
        if running:
            t.append("  │ running…", "yellow")
        t.truncate(max(self.app.size.width, 20) - 1, overflow="ellipsis")
        t = safe(t)
        if t.markup != self.shown:
            self.shown = t.markup
            self.update(t)
