"""The main tabs (Wall … Time history): which one is shown, the focus in it, its ✗ marks."""

from __future__ import annotations

from rich.text import Text
from textual.containers import ScrollableContainer
from textual.widgets import TabPane, Tabs

from frp_assess.tui.core.tabs import TABS
from frp_assess.tui.fields import FieldRow
from frp_assess.tui.results_pane import ResultsPane
from frp_assess.tui.tabbed import Tabbed

#: the widget that gets the focus when a tab is shown
FIRST_FOCUS = {
    "tab-wall": "#f-wall-thickness-control",
    "tab-site": "#f-seismic-spectrum-type-control",
    "tab-records": "#f-seismic-records-source-control",
    "tab-materials": "#materials-editor DataTable",
    "tab-retrofits": "#interventions-editor DataTable",
    "tab-analysis": "#f-analysis-restitution-control",
    "tab-run": "#run-button",
    "tab-results": "#ranking-table",
    "tab-history": "#hist-case",
}


class MainTabs(Tabbed):
    """The tabs of the app; :meth:`show` shows one and puts the focus in it."""

    #: the fields hold the project opened (:meth:`start`): they may be made
    ready = False

    def show(self, tab_id: str) -> None:
        """Show a tab and put the focus on its first field (never on a hidden one)."""
        self.active = tab_id
        self.realize(tab_id)
        self.call_after_refresh(self.focus_in, tab_id)

    def start(self) -> None:
        """The project is in the fields: make those of the tab shown."""
        self.ready = True
        self.realize(self.active or TABS[0][0])

    def realize(self, tab_id: str) -> None:
        """Make the fields of tab ``tab_id``: a field's widgets are made the first time its
        tab is shown (:meth:`FieldRow.realize <frp_assess.tui.fields.FieldRow.realize>`),
        once the project is in the fields (made with their values, they cost less); and the
        results' views (:meth:`ResultsPane.build
        <frp_assess.tui.results_pane.ResultsPane.build>`)."""
        if not self.ready:
            return
        pane = self.query_one(f"#{tab_id}", TabPane)
        with self.app.batch_update():
            for row in pane.query(FieldRow):
                row.realize()
            for results in pane.query(ResultsPane):
                results.build()  # its views too

    def step(self, step: int) -> None:
        """Show the next (``step`` 1) or previous (-1) tab, cyclically."""
        ids = [t for t, _ in TABS]
        i = ids.index(self.active) if self.active in ids else 0
        self.show(ids[(i + step) % len(ids)])

    def focus_in(self, tab_id: str) -> None:
        """Move the focus into tab ``tab_id`` unless it is there (or the tab was left)."""
        if self.active != tab_id:
            return  # the user has moved on
        pane = self.query_one(f"#{tab_id}", TabPane)
        focused = self.screen.focused
        if focused is not None and pane in focused.ancestors:
            return
        first = FIRST_FOCUS.get(tab_id)
        targets = self.query(first) if first is not None else None
        if targets is not None and not targets:
            # not made yet: the results' views are mounted a moment after they are made
            # (ResultsPane.build); come back once they are
            for results in pane.query(ResultsPane):
                if not results.when_ready(lambda: self.focus_in(tab_id)):
                    return
        chain = self.screen.focus_chain  # only widgets that are shown
        if targets and targets.first() in chain:
            targets.first().focus(scroll_visible=False)  # the pane starts at its top
            return
        for widget in chain:
            if pane in widget.ancestors and not isinstance(widget, ScrollableContainer | Tabs):
                widget.focus()
                return
        self.screen.set_focus(None)  # nothing to focus here: never type into a hidden tab

    def on_tabbed_content_tab_activated(self, event: Tabbed.TabActivated) -> None:
        """A tab chosen in the tab bar: the focus follows it (unless on the tab bar)."""
        if event.tabbed_content is not self:
            return
        self.realize(str(event.pane.id))
        focused = self.screen.focused
        if focused is None or (
            not isinstance(focused, Tabs) and event.pane not in focused.ancestors
        ):
            self.call_after_refresh(self.focus_in, str(event.pane.id))

    def mark_problems(self, bad_tabs: set[str]) -> None:
        """Mark the tabs that hold a problem with ✗ (in red)."""
        for tab_id, title in TABS:
            label = f"{title} ✗" if tab_id in bad_tabs else title
            tab = self.get_tab(tab_id)
            if str(tab.label) != label:
                tab.label = Text(label, style="bold red") if tab_id in bad_tabs else label
