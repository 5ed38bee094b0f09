"""A building file in the TUI (issue 41 item 5): the list of walls beside the tabs, each wall
edited with today's tabs, the building saved back with only what changed; walls added,
duplicated, renamed and removed with the file validation's rule for names.  Driven with
Pilot; every wait is for a state of the app, never for time."""

from __future__ import annotations

import difflib
import shutil
from pathlib import Path

import pytest
from textual.widgets import Input, Static

from frp_assess.app.assessment import default_out_dir
from frp_assess.app.building_edit import BuildingDoc
from frp_assess.app.building_summary_file import load_building_summary
from frp_assess.cli import main
from frp_assess.config.walls_file import load_building
from frp_assess.errors import InputError
from frp_assess.results.building_rows import check_rows
from frp_assess.tui.building_app import BuildingApp, WallList, open_app
from frp_assess.tui.dialogs import NamePrompt
from tests.tui.conftest import run_async, settle
from tests.tui.test_app import SIZE, plain, type_into

FIXTURE = Path(__file__).parents[1] / "fixtures" / "building-small.yaml"
NAMES = ["Facciata sud, piano terra", "Timpano est", "Parapetto"]


@pytest.fixture
def building(tmp_path: Path) -> Path:
    path = tmp_path / "casa.yaml"
    shutil.copy(FIXTURE, path)
    return path


def changed_lines(before: str, after: str) -> list[str]:
    """The lines removed (-) and added (+) from ``before`` to ``after``."""
    diff = difflib.unified_diff(before.splitlines(), after.splitlines(), lineterm="", n=0)
    return [d for d in diff if d[:1] in "+-" and d[:3] not in ("+++", "---")]


def test_the_doc_writes_a_wall_key_into_its_item_and_a_shared_key_at_the_top() -> None:
    """The one-wall project of walls[1] edited: its height goes to walls[1].height, the
    site's ag to seismic.spectrum.ag (shared by every wall); the text changes on those two
    lines only, comments kept."""
    text = FIXTURE.read_text(encoding="utf-8")
    doc = BuildingDoc.from_text(text, "casa.yaml")
    shown, problem = doc.show(1)
    assert problem == "" and shown["wall"]["height"] == 2.5
    shown["wall"]["height"] = 2.75
    shown["seismic"]["spectrum"]["ag"] = 0.3
    doc.store(shown)
    assert doc.data["walls"][1]["height"] == 2.75 and doc.data["walls"][0]["height"] == 3.5
    assert doc.data["seismic"]["spectrum"]["ag"] == 0.3
    out = doc.text(text)
    assert sorted(changed_lines(text, out)) == sorted(
        [
            "-  spectrum: {type: ntc2018, ag: 0.261, F0: 2.36, Tc_star: 0.347, soil: B, "
            "topography: T1}",
            "+  spectrum: {type: ntc2018, ag: 0.3, F0: 2.36, Tc_star: 0.347, soil: B, "
            "topography: T1}",
            "-    height: 2.5",
            "+    height: 2.75",
        ]
    )


def test_the_doc_refuses_a_name_with_the_file_validations_message() -> None:
    doc = BuildingDoc.from_text(FIXTURE.read_text(encoding="utf-8"), "casa.yaml")
    problem = doc.duplicate(2, "Timpano est")
    assert problem == "casa.yaml: walls[3].name: 'Timpano est' is already the name of walls[1]"
    assert doc.names() == NAMES  # unchanged
    assert "at least one" in BuildingDoc.from_text("walls: [{name: a}]\n").remove(0)


def test_a_one_wall_project_opens_in_todays_app(small_project: Path, building: Path) -> None:
    assert type(open_app(small_project)).__name__ == "FrpAssessApp"
    assert isinstance(open_app(building), BuildingApp)


def test_switch_walls_edit_one_and_save_changes_only_that_value(building: Path) -> None:
    """Open the building, see its walls, switch to the second, change its height, save:
    the file reads back with that one value changed (and its comments kept)."""
    before = building.read_text(encoding="utf-8")

    async def body() -> None:
        app = open_app(building)
        assert isinstance(app, BuildingApp)
        async with app.run_test(size=SIZE) as pilot:
            await settle(pilot, lambda: app.project is not None)
            walls = app.query_one(WallList)
            assert [str(walls.get_option_at_index(i).prompt) for i in range(3)] == NAMES
            height = app.query_one("#f-wall-height-control", Input)
            assert height.value == "3.5" and not app.modified()
            walls.focus()
            await pilot.press("down", "enter")
            await settle(pilot, lambda: height.value == "2.5")
            assert app.doc.current == 1 and not app.modified()
            await type_into(pilot, "#f-wall-height-control", "2.75")
            await settle(pilot, lambda: app.modified())
            walls.focus()
            await pilot.press("up", "enter")  # back to the first wall: the edit is kept
            await settle(pilot, lambda: height.value == "3.5")
            assert app.modified()
            await pilot.press("ctrl+s")
            await settle(pilot, lambda: not app.modified())
        after = building.read_text(encoding="utf-8")
        assert changed_lines(before, after) == ["-    height: 2.5", "+    height: 2.75"]
        loaded = load_building(building)
        assert loaded.wall("Timpano est").loaded.project.wall.height == 2.75

    run_async(body)


def test_add_duplicate_rename_remove_walls(building: Path) -> None:
    """The list's keys: a duplicate named as an existing wall is refused with the file's
    message (the dialog stays); renamed, added and removed walls are saved in the file."""

    async def body() -> None:
        app = open_app(building)
        assert isinstance(app, BuildingApp)
        async with app.run_test(size=SIZE) as pilot:
            await settle(pilot, lambda: app.project is not None)
            walls = app.query_one(WallList)
            walls.focus()
            await pilot.press("d")  # duplicate the first wall
            await settle(pilot, lambda: isinstance(app.screen, NamePrompt))
            app.screen.query_one(Input).value = "Timpano est"
            await pilot.press("enter")
            await settle(
                pilot,
                lambda: "already the name" in str(app.screen.query_one("#path-error").render()),
            )
            app.screen.query_one(Input).value = "Facciata nord"
            await pilot.press("enter")
            await settle(pilot, lambda: app.doc.names()[1] == "Facciata nord")
            assert app.doc.current == 1 and walls.option_count == 4
            await pilot.press("r")  # rename it
            await settle(pilot, lambda: isinstance(app.screen, NamePrompt))
            app.screen.query_one(Input).value = "Facciata nord, piano terra"
            await pilot.press("enter")
            await settle(pilot, lambda: "Facciata nord, piano terra" in app.doc.names())
            walls.focus()
            await pilot.press("a")  # add a wall at the end
            await settle(pilot, lambda: isinstance(app.screen, NamePrompt))
            app.screen.query_one(Input).value = "Muro di cinta"
            await pilot.press("enter")
            await settle(pilot, lambda: app.doc.current == 4)
            walls.focus()
            walls.highlighted = 3  # Parapetto
            await pilot.press("delete")
            await settle(pilot, lambda: "Parapetto" not in app.doc.names())
            await pilot.press("ctrl+s")
            await settle(pilot, lambda: not app.modified())
        loaded = load_building(building)
        assert loaded.names() == [
            "Facciata sud, piano terra",
            "Facciata nord, piano terra",
            "Timpano est",
            "Muro di cinta",
        ]
        first, copied = loaded.walls[0].loaded.project, loaded.walls[1].loaded.project
        assert copied.wall == first.wall  # a duplicate: the same wall
        assert "# A small building for the tests" in building.read_text(encoding="utf-8")

    run_async(body)


@pytest.mark.slow
def test_the_building_summary_is_the_first_results_view(building: Path) -> None:
    """After `frp-assess run` of the building, its Results tab opens on the building
    summary: a row per wall with the cells of the console's tables (the same row builders,
    results/building_rows.py, read from OUT/results.json), then the governing wall."""
    assert main(["run", str(building), "--no-pdf"]) == 0
    summary = load_building_summary(default_out_dir(building))
    assert summary is not None
    rows = check_rows(summary)

    async def body() -> None:
        app = open_app(building)
        async with app.run_test(size=(140, 40)) as pilot:
            await pilot.press("f9")
            view = app.query_one("#building-summary", Static)
            await settle(pilot, lambda: "governing mechanism" in plain(view))
            shown = plain(view)
            for row in rows:  # each wall: its name and every ζ_E, as the console prints them
                line = next(t for t in shown.splitlines() if row[1] in t and row[2] in t)
                assert all(cell in line for cell in row[1:] if cell != "—")
            for name in NAMES:
                assert name.split(",")[0] in shown
            assert f"governing mechanism: {summary.totals.governing_wall}" in shown

    run_async(body)


def test_a_one_wall_results_json_is_not_taken_for_a_buildings(tmp_path: Path) -> None:
    (tmp_path / "results.json").write_text('{"schema_version": 1}', encoding="utf-8")
    with pytest.raises(InputError, match="expected a building's results"):
        load_building_summary(tmp_path)
    assert load_building_summary(tmp_path / "none") is None
