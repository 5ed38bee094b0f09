"""The TUI of issue 39: the results next to a project file always belong to the file as saved
(ctrl+r on unsaved edits runs in a scratch folder, and says so); the export dialog proposes a
folder of its own; the ranking, the tab bar, the help and the notifications at the sizes a
user has (100 and 120 columns).

Driven with Pilot; every wait is for a state of the app (tests/tui/conftest.py), never for
time.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from rich.console import Console
from textual.widgets import DataTable, Input, Static, TabbedContent, Tabs
from textual.widgets._toast import Toast

from frp_assess.api import default_out_dir
from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.help import HELP_TEXT
from frp_assess.tui.ranking_table import RankingTable
from frp_assess.tui.results_pane import SCRATCH_NOTE, STALE_TITLE
from tests.tui.conftest import after_workers, run_async, settle


def shown(widget: Static) -> str:
    """What a Static shows, as one line of plain text."""
    console = Console(width=400, record=True, file=open("/dev/null", "w"))  # noqa: SIM115
    console.print(widget.content)
    return " ".join(console.export_text().split())


def log_text(app: FrpAssessApp) -> str:
    log = app.query_one("#run-log")
    return " ".join("".join(str(line.text) for line in log.lines).split())


@pytest.mark.slow
def test_unsaved_edits_never_run_into_the_saved_projects_folder(
    small_project: Path, tmp_path: Path
) -> None:
    """Edit B, ctrl+r without saving: the results go to a scratch folder (the log and the
    Results tab say so), the project's own results folder is not written; the export dialog
    refuses that folder for them.  Saved, the next run writes next to the file."""
    saved_dir = default_out_dir(small_project)

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=(100, 30)) as pilot:
            await pilot.pause()
            box = app.query_one("#f-wall-thickness-control", Input)
            box.value = "0.35"
            await settle(pilot, lambda: app.modified() and app.project is not None)
            await pilot.press("ctrl+r")
            await after_workers(pilot, lambda: not app.running and app.outcome is not None)
            assert app.outcome is not None and app.scratch is not None
            assert app.outcome.out_dir == app.scratch
            assert (app.scratch / "results.json").is_file()
            assert not saved_dir.exists()  # nothing of the edits next to the file
            assert "unsaved edits: they run in the scratch folder" in log_text(app)
            note_widget = app.query_one("#results-note", Static)
            note = shown(note_widget)
            assert " ".join(SCRATCH_NOTE.split()) in note and str(app.scratch) in note
            # the note wraps at 100 columns instead of being cut at its first line
            await pilot.press("f9")
            await settle(pilot, lambda: note_widget.size.height >= len(note) // 100 + 1 > 1)
            # the export: proposed elsewhere, and never into the saved file's folder
            await pilot.press("ctrl+e")
            await settle(pilot, lambda: bool(app.screen.query("#path-input")))
            path = app.screen.query_one("#path-input", Input)
            assert path.value == str(small_project.with_name("small-export"))
            path.value = str(saved_dir)
            await pilot.press("enter")
            error = app.screen.query_one("#path-error", Static)
            await settle(pilot, lambda: "unsaved edits" in shown(error))
            await pilot.press("escape")
            await settle(pilot, lambda: not app.screen.query("#path-input"))
            assert not saved_dir.exists()
            # saved, the run writes next to the file, with the file's own B
            await pilot.press("ctrl+s")
            await settle(pilot, lambda: not app.modified())
            await pilot.press("ctrl+r")
            await after_workers(
                pilot,
                lambda: not app.running and app.outcome is not None and saved_dir.exists(),
            )
            assert app.outcome is not None and app.outcome.out_dir == saved_dir
            assert app.outcome.results.wall.thickness == 0.35
            assert "Results of the last run" in shown(app.query_one("#results-note", Static))
            scratch = app.scratch
            assert scratch is not None and scratch.is_dir()
            app.quit_now()  # the scratch folder goes with the session
        assert not scratch.exists() and saved_dir.is_dir()

    run_async(body)


def _columns_fit(table: DataTable) -> bool:
    """Every column of ``table`` is shown whole in its width (no horizontal scrolling)."""
    used = sum(c.get_render_width(table) for c in table.columns.values())
    return used <= table.scrollable_content_region.width


@pytest.mark.slow
def test_ranking_tab_bar_help_and_views_at_a_users_sizes(small_project: Path) -> None:
    """At 120 columns the ranking's columns fit whole (the margin column was cut); at 100 the
    main tab bar holds every tab, the stale Results title included (the header was cut); the
    time-history viewer is named so; ``]`` / ``[`` move between the Results views, and the
    help says so; a notification does not cover the run log's last line."""

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=(120, 30), notifications=True) as pilot:
            await pilot.pause()
            await pilot.press("ctrl+r")
            await after_workers(pilot, lambda: not app.running and app.outcome is not None)
            # the notification "run finished" and the log's last line (the outcome)
            await settle(pilot, lambda: bool(app.screen.query(Toast)))
            log = app.query_one("#run-log")
            last_line = log.content_region.bottom - 1
            for toast in app.screen.query(Toast):
                assert not (toast.region.y <= last_line < toast.region.bottom)
            await pilot.press("f9")
            table = app.query_one(RankingTable)
            await settle(pilot, lambda: app.focused is table and table.row_count == 3)
            assert _columns_fit(table)
            headers = [str(c.label).split(" ")[0] for c in table.columns.values()]
            assert headers[-3:] == ["verdict", "governs", "margin"]
            # the Results views: ] next, [ previous (cyclic)
            views = app.query_one("#results-tabs", TabbedContent)
            assert views.active == "res-ranking"
            await pilot.press("right_square_bracket")
            await settle(pilot, lambda: views.active == "res-records")
            await pilot.press("left_square_bracket", "left_square_bracket")
            await settle(pilot, lambda: views.active == "res-compliance")
            # 100 columns: every main tab, the stale title included, in the bar
            await pilot.resize_terminal(100, 30)
            tabs = app.query_one("#tabs", TabbedContent)
            tabs.get_tab("tab-results").label = STALE_TITLE
            bar = tabs.query_one(Tabs)
            await settle(pilot, lambda: bar.size.width == 100)
            labels = [str(t.label) for t in bar.query("Tab")]
            assert "Time history" in labels and STALE_TITLE in labels
            await settle(pilot, lambda: all(t.region.right <= 100 for t in bar.query("Tab")))

    run_async(body)
    help_text = " ".join(HELP_TEXT.split())
    assert "`]` next view, `[` previous view" in help_text
    assert "Time history" in help_text and "scratch folder" in help_text
