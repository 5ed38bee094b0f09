"""A tab's fields are made the first time it is shown (frp_assess/tui/fields.py, ``FieldRow``).

Until then a field keeps what its control would hold; the reference here is the control
itself: every field answers the same value before and after its widgets are made, the
project collected from the fields is the same, and a field's message, unknown choice and
placeholder show once it is made.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from textual.widgets import Input, OptionList, Select, Static

from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.core.tabs import TABS
from frp_assess.tui.fields import FieldRow
from frp_assess.tui.main_tabs import MainTabs
from frp_assess.tui.materials import MaterialsEditor
from tests.tui.conftest import SMALL, run_async, show_tab
from tests.tui.test_app import SIZE

#: values away from the defaults in every editor tab: a word the schema does not know
#: (shown as ``bogus (?)`` with its message), lists, an optional number, a text with markup
PROJECT = (
    SMALL.replace("{name: Small wall}", "{name: '[bold]North[/bold] wall', engineer: A. B.}")
    + "analysis: {collapse: bogus, pivot: edge, strain_factor: 0.7}\n"
    + "code_check: {fc_in_ida: false}\n"
    + "design: {materials: [GFRP, CFRP], positions: [external], resolution: 0.05}\n"
).replace("seed: 7,", "seed: 11,")

EDITOR_TABS = [tab for tab, _ in TABS[:6]]  # Wall ... Analysis: the tabs with fields


def rows_in(app: FrpAssessApp, tab_id: str) -> list[FieldRow]:
    return list(app.query_one(f"#{tab_id}").query(FieldRow))


def key(row: FieldRow) -> str:
    return str(row.id)


def error_line(row: FieldRow) -> str:
    lines = row.query(".f-error")
    return str(lines.first(Static).content) if lines else ""


@pytest.mark.slow
def test_fields_hold_the_same_values_before_and_after_their_widgets_are_made(tmp_path: Path):
    path = tmp_path / "wall.yaml"
    path.write_text(PROJECT, encoding="utf-8")

    async def body() -> None:
        app = FrpAssessApp(path)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            # opening makes the fields of the tab shown only
            assert all(r.live for r in rows_in(app, "tab-wall"))
            for tab in EDITOR_TABS[1:]:
                assert rows_in(app, tab) and not any(r.realized for r in rows_in(app, tab))
            every = list(app.query(FieldRow))  # the tables' forms too
            before = {key(r): r.data_value() for r in every}
            errors = {key(r): r.error for r in every}
            data = app.form.collect()
            assert errors["f-analysis-collapse"] is not None  # 'bogus' is no criterion
            assert app.problems and not app.modified()

            for tab in EDITOR_TABS[1:]:
                await show_tab(pilot, tab)
            await pilot.pause()
            assert all(r.live for r in every)
            assert {key(r): r.data_value() for r in every} == before
            assert {key(r): r.error for r in every} == errors
            assert app.form.collect() == data and not app.modified()

            # what the controls show: the value read from the file, the unknown word kept
            # as an option of its own, the message under its field
            q = app.query_one
            assert q("#f-analysis-pivot-control", Select).value == "edge"
            assert q("#f-code-check-fc-in-ida-control", Select).value is False
            assert q("#f-analysis-strain-factor-control", Input).value == "0.7"
            assert q("#f-design-materials-on-control", Input).value == "GFRP, CFRP"
            collapse = q("#f-analysis-collapse-control", Select)
            assert collapse.value == "bogus"
            listed = collapse.query_one(OptionList)
            n = listed.option_count
            prompts = [str(listed.get_option_at_index(i).prompt) for i in range(n)]
            assert prompts[-1] == "bogus (?)"
            row = q("#f-analysis-collapse", FieldRow)
            assert row.error is not None and error_line(row) == f"✗ {row.error}"
            assert row.has_class("-error")
            # the Materials form: a library material's values are the inputs' placeholders
            materials = q(MaterialsEditor)
            modulus = next(
                r for r in materials.form_rows("material") if r.spec.path == ("elastic_modulus",)
            )
            control = modulus.control
            assert isinstance(control, Input) and control.placeholder == "46 (library)"  # GFRP

    run_async(body)


@pytest.mark.slow
def test_a_value_set_while_a_field_is_being_made_is_the_one_shown(small_project: Path):
    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            t1 = app.query_one("#f-seismic-t1", FieldRow)
            count = app.query_one("#f-seismic-records-artificial-count-artificial", FieldRow)
            kind = app.query_one("#f-seismic-spectrum-type", FieldRow)
            assert not (t1.realized or count.realized or kind.realized)
            app.query_one(MainTabs).realize("tab-site")  # made, not mounted yet
            assert t1.realized and not t1.live
            t1.set_value(0.85)
            kind.set_value("ec8")
            t1.show_error("a message")
            count.set_value(5)  # a tab not shown: kept without widgets
            await pilot.pause()
            assert t1.live and kind.live and not count.realized
            values: dict[str, Any] = {
                "t1": t1.control.value,
                "type": kind.control.value,
                "t1 data": t1.data_value(),
                "count data": count.data_value(),
            }
            assert values == {"t1": "0.85", "type": "ec8", "t1 data": 0.85, "count data": 5}
            assert error_line(t1) == "✗ a message"

    run_async(body)
