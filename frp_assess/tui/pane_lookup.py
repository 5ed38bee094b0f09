"""The app's lookup of its panes, which tolerates their absence while the app closes.

Textual shuts an app down by removing its screen and only then handling the messages still
queued (the ranking table's ``CaseChosen`` posted when it was filled, a worker's ``RunDone``):
a handler that looked its pane up with ``query_one`` then raised ``NoMatches`` and the app
ended in an error. The handlers look panes up with :meth:`PaneLookupApp.pane` and drop the
message when it returns None.
"""

from __future__ import annotations

from typing import TypeVar

from textual.app import App
from textual.css.query import NoMatches
from textual.widget import Widget

W = TypeVar("W", bound=Widget)


class PaneLookupApp(App[None]):
    """An app whose message handlers find their panes with :meth:`pane`."""

    quitting: bool = False  #: set when the user quits (the workers are stopped)

    @property
    def closing(self) -> bool:
        """Whether the app is closing: asked to quit (by the user or Textual's ``exit``) or
        being shut down (its screen removed before its last messages are handled)."""
        return self.quitting or self.return_code is not None or not self.is_running

    def pane(self, kind: type[W]) -> W | None:
        """The mounted widget of ``kind``; None when the app is closing or it is not
        mounted (the message that asked for it is then dropped)."""
        if self.closing:
            return None
        try:
            return self.query_one(kind)
        except NoMatches:
            return None


__all__ = ["PaneLookupApp"]
