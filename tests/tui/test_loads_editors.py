"""The Wall tab's loads tables (``wall.loads``, docs/model.md §12) driven with Pilot: a file
with loads opens into them unchanged, a tie is added from its table, a load outside the wall
shows the message `validate` prints under its field, and what is saved reads back."""

from __future__ import annotations

from pathlib import Path

from textual.widgets import Input

from frp_assess.config import load_project
from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.loads_editors import ThrustsEditor, TiesEditor, TopLoadsEditor
from tests.tui.conftest import SMALL, run_async, settle, show_tab
from tests.tui.test_app import SIZE, type_into

LOADED = SMALL.replace(
    "       mechanism: one-sided}",
    "       mechanism: one-sided,\n"
    "       loads: {top: [{name: floor, load: 8.0, distance: 0.2}],\n"
    "               thrust: [{force: 0.5, height: 2.5}]}}",
)


def test_loads_tables_open_edit_validate_and_save(tmp_path: Path) -> None:
    path = tmp_path / "loaded.yaml"
    assert LOADED != SMALL
    path.write_text(LOADED, encoding="utf-8")

    async def body() -> None:
        app = FrpAssessApp(path)
        async with app.run_test(size=SIZE) as pilot:
            await show_tab(pilot, "tab-wall")
            top, thrusts = app.query_one(TopLoadsEditor), app.query_one(ThrustsEditor)
            ties = app.query_one(TiesEditor)
            await settle(pilot, lambda: app.project is not None)
            # the project's data as the loader gives it, the schema's defaults filled in
            assert top.items == [
                {"name": "floor", "load": 8.0, "distance": 0.2, "inertia": "carried"}
            ]
            assert len(thrusts.items) == 1 and ties.items == []
            assert not app.modified()
            await pilot.press("ctrl+s")  # unchanged: the file stays byte for byte
            await pilot.pause()
            assert path.read_text(encoding="utf-8") == LOADED
            ties.table.focus()
            await settle(pilot, lambda: app.focused is ties.table)
            await pilot.press("a")  # a tie, from its table
            await settle(
                pilot,
                lambda: (
                    app.project is not None
                    and app.project.wall.loads is not None
                    and len(app.project.wall.loads.ties) == 1
                ),
            )
            assert app.modified()
            distance = next(r for r in top.form_rows("top") if r.spec.path == ("distance",))
            assert isinstance(distance.control, Input)
            await type_into(pilot, f"#{distance.control.id}", "0.45")
            message = "expected 0 <= distance <= B = 0.3 m (the line of action inside the wall)"
            await settle(pilot, lambda: bool(app.problems))
            assert str(app.problems[0]) == f"wall.loads.top[0].distance: {message}, found 0.45"
            assert distance.error == f"{message}, found 0.45"
            await type_into(pilot, f"#{distance.control.id}", "0.25")
            await settle(pilot, lambda: app.problems == [])
            await pilot.press("ctrl+s")
            await settle(pilot, lambda: not app.modified())
            saved = load_project(path).project
            assert saved == app.project
            assert saved.wall.loads is not None
            assert [p.distance for p in saved.wall.loads.top] == [0.25]
            assert len(saved.wall.loads.ties) == 1 and len(saved.wall.loads.thrust) == 1
            thrusts.table.focus()
            await settle(pilot, lambda: app.focused is thrusts.table)
            await pilot.press("delete")
            await settle(pilot, lambda: thrusts.items == [])
            assert app.form.collect()["wall"]["loads"]["thrust"] == []
            top.table.focus()
            await settle(pilot, lambda: app.focused is top.table)
            await pilot.press("delete")
            ties.table.focus()
            await settle(pilot, lambda: app.focused is ties.table)
            await pilot.press("delete")
            await settle(pilot, lambda: top.items == [] and ties.items == [])
            assert "loads" not in app.form.collect()["wall"]  # a free-standing wall again

    run_async(body)
