"""The Retrofits tab with a tie option (``type: tie``, docs/model.md §12), driven with Pilot:
``t`` adds a tie from the options table, its row and its form show the tie, a height above
the wall shows the message `validate` prints under its field, the options compared show its
kind and steel per metre, and what is saved reads back as a tie option."""

from __future__ import annotations

import io
from pathlib import Path

import pytest
from rich.console import Console
from textual.widgets import Input

from frp_assess.config import load_project
from frp_assess.config.schema import TieOption
from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.interventions import InterventionsEditor
from frp_assess.tui.retrofits_pane import RetrofitsPane, options_table
from tests.tui.conftest import run_async, settle
from tests.tui.test_app import SIZE, type_into


def _shown(app: FrpAssessApp) -> str:
    """The options compared, as the Retrofits tab draws them (plain text)."""
    key = app.query_one(RetrofitsPane).shown.get("#expanded-options")
    if not key:
        return ""
    console = Console(width=160, record=True, file=io.StringIO())
    console.print(options_table(*key))
    return console.export_text()


@pytest.mark.slow
def test_a_tie_option_is_added_edited_shown_and_saved(small_project: Path) -> None:
    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            await pilot.press("f6")
            editor = app.query_one(InterventionsEditor)
            await settle(pilot, lambda: app.focused is editor.table)
            n = len(editor.items)
            await pilot.press("t")  # a tie option
            await settle(pilot, lambda: len(editor.items) == n + 1 and app.project is not None)
            assert app.project is not None
            last = app.project.interventions[-1]
            assert isinstance(last, TieOption)
            row = editor.table.get_row_at(n)
            assert str(row[1]) == "tie" and str(row[2]) == "Tie Ø20 @ 3.0 m at 3.0 m"
            height = next(r for r in editor.form_rows("tie") if r.spec.path == ("height",))
            assert isinstance(height.control, Input) and height.control.value == "3"
            wall_h = float(app.project.wall.height)
            await type_into(pilot, f"#{height.control.id}", f"{wall_h + 1:g}")
            message = f"expected a tie on the wall, 0 < height <= H = {wall_h:g} m"
            await settle(pilot, lambda: bool(app.problems))
            assert str(app.problems[0]).startswith(f"interventions[{n}].height: {message}")
            await type_into(pilot, f"#{height.control.id}", f"{wall_h / 2:g}")
            await settle(pilot, lambda: app.problems == [])
            await settle(pilot, lambda: "tie steel [kg/m]" in _shown(app))
            # ρ·A_s·L_t/i_t = 7850·π·0.02²/4·8/3 = 6.58 kg/m
            assert "6.58" in _shown(app)
            await pilot.press("ctrl+s")
            await settle(pilot, lambda: not app.modified())

    run_async(body)
    saved = load_project(small_project).project
    last = saved.interventions[-1]
    assert isinstance(last, TieOption) and last.diameter == 20.0
    assert last.height == pytest.approx(float(saved.wall.height) / 2)
