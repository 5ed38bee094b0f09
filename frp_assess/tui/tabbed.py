"""Tabs whose active tab is changed on purpose only (never by the focus moving)."""

from __future__ import annotations

from textual.widgets import TabbedContent, TabPane


class Tabbed(TabbedContent):
    """TabbedContent whose tab is chosen by the tab bar and by the app, never by the focus.

    ``TabbedContent`` switches to the pane of any widget that gets the focus; a focus
    message that arrives late (the first field focused at start, processed after the user
    pressed F10) then sent the user back to a tab they had left.  Here the tab is only
    changed on purpose, and the app moves the focus into the tab shown
    (:meth:`MainTabs.show <frp_assess.tui.main_tabs.MainTabs.show>`), so the focus follows
    the tab and never the reverse.
    """

    def on_tab_pane_focused(self, event: TabPane.Focused) -> None:
        event.stop()
        event.prevent_default()  # TabbedContent's own handler would switch the tab
