"""Messages that arrive when the panes they update are gone are dropped, not raised.

The ranking table posts ``CaseChosen`` when it is filled (its cursor lands on a row); a run's
worker posts ``RunProgress``/``RunDone``. When the app closes right after (a test leaving
``run_test``, a user quitting as a run finishes), Textual removes the screen and only then
handles the last queued messages: a handler that looked its pane up raised ``NoMatches`` and
the app ended in an error (seen once in ``test_a_run_from_the_tui_uses_the_projects_bars``).
These tests produce that ordering deterministically, with no sleep: the message is posted by
the pane itself as it is removed, or after the panes were removed.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from textual.message import Message
from textual.widgets import TabbedContent

from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.history_pane import HistoryPane
from frp_assess.tui.ranking_table import RankingTable
from frp_assess.tui.worker_messages import ExportDone, PreviousLoaded, RunDone
from tests.tui.conftest import run_async

SIZE = (100, 30)


def app_messages() -> list[Message]:
    """One of each message the app's own handlers take from panes and worker threads."""
    return [
        RankingTable.CaseChosen(0),
        RunDone("cancelled", "cancelled", None),
        PreviousLoaded(None, "not found"),
        ExportDone([], "disk full"),
    ]


@pytest.mark.tui
def test_a_case_chosen_during_shutdown_is_dropped(monkeypatch: pytest.MonkeyPatch):
    """The failure seen: the app handles ``CaseChosen`` after Textual began removing its
    screen (posted here by the history pane as it is unmounted, which is while the screen
    goes: its children are removed before it)."""
    posted: list[int] = []

    def on_unmount(pane: HistoryPane) -> None:
        pane.app.post_message(RankingTable.CaseChosen(0))
        posted.append(0)

    monkeypatch.setattr(HistoryPane, "on_unmount", on_unmount, raising=False)

    async def body() -> None:
        app = FrpAssessApp(None)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
        # leaving run_test shuts the app down; with the bug it re-raises NoMatches here

    run_async(body)
    assert posted == [0]  # the ordering was produced


@pytest.mark.tui
def test_messages_for_panes_removed_are_dropped(small_project: Path):
    """Each message the app routes to a pane is dropped when the panes are not mounted
    (the tabs, status bar and help line removed), and the app stays up (one app for all:
    a handler that raised would end it, and leaving ``run_test`` re-raises its error)."""

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            await app.query_one("#tabs", TabbedContent).remove()
            await app.query_one("#status").remove()
            await app.query_one("#help-line").remove()
            for message in app_messages():
                app.post_message(message)
                await pilot.pause()
                assert app.is_running and app.return_code is None, type(message).__name__

    run_async(body)
