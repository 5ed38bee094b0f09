"""The TUI edits the category of the intervention (code_check.intervention, use_class,
school; NTC 2018 §8.4): a file's values show in the Analysis tab, edits reach the project
and the save."""

from __future__ import annotations

from pathlib import Path

import pytest
from textual.widgets import Select

from frp_assess.config import load_project
from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.field_specs import CODE_FIELDS
from tests.tui.conftest import SMALL, run_async, settle, show_tab
from tests.tui.test_app import SIZE


def test_the_three_categories_are_offered_with_their_clauses() -> None:
    spec = next(f for f in CODE_FIELDS if f.path == ("code_check", "intervention"))
    assert [value for _, value in spec.choices] == ["local", "improvement", "upgrade"]
    assert [label for label, _ in spec.choices] == [
        "local (§8.4.1)",
        "improvement (§8.4.2)",
        "upgrade (§8.4.3)",
    ]


@pytest.mark.slow
def test_an_improvement_of_a_class_iv_building_is_edited_and_saved(tmp_path: Path) -> None:
    path = tmp_path / "wall.yaml"
    path.write_text(SMALL + "code_check: {intervention: local}\n", encoding="utf-8")

    async def body() -> None:
        app = FrpAssessApp(path)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            q = app.query_one
            await show_tab(pilot, "tab-analysis")
            assert q("#f-code-check-intervention-control", Select).value == "local"
            q("#f-code-check-use-class-control", Select).value = "IV"
            q("#f-code-check-intervention-control", Select).value = "improvement"
            await settle(
                pilot,
                lambda: (
                    app.project is not None
                    and app.project.code_check.intervention == "improvement"
                    and app.project.code_check.use_class == "IV"
                ),
            )
            await pilot.press("ctrl+s")
            await settle(pilot, lambda: not app.modified())

    run_async(body)
    saved = load_project(path).project.code_check
    assert (saved.intervention, saved.use_class, saved.school) == ("improvement", "IV", False)
