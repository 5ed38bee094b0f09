"""The Results tab says when the project file changed since the run shown: the digest of the
project as it is on disk is not the results' ``inputs_digest`` (frp_assess/app/rerun.py)."""

from __future__ import annotations

from pathlib import Path

from frp_assess.cli import main
from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.results_pane import STALE_TITLE
from tests.tui.conftest import after_workers, run_async


def _results_label(app: FrpAssessApp) -> str:
    from textual.widgets import TabbedContent

    return str(app.query_one("#tabs", TabbedContent).get_tab("tab-results").label)


def _opened_label(project: Path) -> str:
    """Open ``project`` in the TUI, wait for its last run to be shown, return the tab's title."""

    async def body() -> str:
        app = FrpAssessApp(project, jobs=1)
        async with app.run_test(size=(120, 40)) as pilot:
            await pilot.pause()
            await after_workers(pilot, lambda: app.outcome is not None)
            return _results_label(app)

    label = run_async(body)
    assert isinstance(label, str)
    return label


def test_results_of_a_changed_project_file_are_marked_stale(small_project: Path) -> None:
    assert main(["run", str(small_project), "--no-pdf", "--jobs", "1"]) == 0
    assert _opened_label(small_project) == "Results"
    # a new name: the IDAs are all cached (the last run is shown again), the file is not the run's
    text = small_project.read_text(encoding="utf-8")
    small_project.write_text(text.replace("Small wall", "Small wall renamed"), encoding="utf-8")
    assert _opened_label(small_project) == STALE_TITLE
