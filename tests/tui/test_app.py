"""The TUI driven with Pilot on a 100 x 30 terminal: edit, validate, run, cancel, save, export."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from rich.console import Console
from textual.widgets import DataTable, Input, Select, Static, TabbedContent, TabPane

from frp_assess.api import CACHE_DIR, default_out_dir, run_assessment, template_text
from frp_assess.app.rerun import inputs_digest, unchanged_run
from frp_assess.assess.from_project import inputs_from_project
from frp_assess.config import load_project, load_project_text
from frp_assess.results.json_io import from_json
from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.help import HelpScreen
from frp_assess.tui.interventions import InterventionsEditor
from frp_assess.tui.ranking_table import RankingTable
from frp_assess.tui.run_panel import RunPanel
from tests.tui.conftest import after_workers, run_async, settle

SIZE = (100, 30)


def plain(widget: Static) -> str:
    """What a Static shows, as plain text."""
    console = Console(width=100, record=True, file=open("/dev/null", "w"))  # noqa: SIM115
    console.print(widget.content)
    return console.export_text()


async def type_into(pilot: Any, selector: str, text: str) -> None:
    """Focus an input, clear it and type ``text`` key by key (as a person would)."""
    app = pilot.app
    box = app.query_one(selector, Input)
    box.focus()
    box.value = text[:-1]  # as if typed up to the last key...
    box.cursor_position = len(box.value)
    await pilot.press(text[-1])  # ...which is pressed
    await pilot.pause()


def log_text(log: Any) -> str:
    """What the run log shows, as plain text."""
    return "".join(str(line.text) for line in log.lines)


def history_shown(app: FrpAssessApp) -> bool:
    """The History tab is shown with the θ/α plot of a computed time history."""
    tabs = app.query_one("#tabs", TabbedContent)
    return tabs.active == "tab-history" and "θ/α" in app.query_one("#hist-theta").render().plain


def row_error(app: FrpAssessApp, path: tuple[str, ...]) -> str | None:
    row = next(r for r in app.rows if r.spec.path == path)
    return row.error


@pytest.mark.slow
def test_open_edit_derived_values_and_validation_messages(small_project: Path):
    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            assert app.problems == [] and app.project is not None
            assert app.query_one("#f-wall-thickness-control", Input).value == "0.3"
            derived = app.query_one("#derived-wall", Static)
            assert "5.711°" in plain(derived)  # atan(0.3/3)
            assert "0.1060 g" in plain(derived)  # a_g·S of preset A2

            # a change updates the derived values as it is typed
            await type_into(pilot, "#f-wall-thickness-control", "0.4")
            assert "7.595°" in plain(derived)
            # a_RM = (B − x_W)/H about the crushing pivot (the run's model): solid brick and
            # lime mortar, Circolare 2019 Tab. C8.5.I f_m = 2.6 MPa, LC1 FC = 1.35,
            # x_W = 18 kN/m³·0.4·3 / (0.85·2.6/1.35 MPa) = 13.2 mm: (0.4 − 0.0132)/3 = 0.1289 g
            assert "0.1289 g" in plain(derived)
            assert app.project is not None and app.project.wall.thickness == 0.4

            # thickness >= height: the loader's own message, under the field
            await type_into(pilot, "#f-wall-thickness-control", "3.5")
            message = "expected thickness B < height H = 3 m, found 3.5 (a rocking wall is slender)"
            assert row_error(app, ("wall", "thickness")) == message
            assert app.problems[0].message == message and app.project is None
            assert "Wall ✗" in str(app.query_one("#tabs", TabbedContent).get_tab("tab-wall").label)
            assert "✗ wall.thickness: expected thickness" in plain(app.query_one("#status", Static))

            # text in a number field
            await type_into(pilot, "#f-wall-height-control", "abc")
            assert row_error(app, ("wall", "height")) == "expected a number, found 'abc'"

            # fixing both clears the messages
            await type_into(pilot, "#f-wall-height-control", "3")
            await type_into(pilot, "#f-wall-thickness-control", "0.3")
            assert app.problems == []
            assert row_error(app, ("wall", "thickness")) is None

            # the site spectrum: switch the type, the preview follows
            await pilot.press("f3")
            await pilot.pause()
            kind = app.query_one("#f-seismic-spectrum-type-control", Select)
            kind.value = "ntc2018"
            await settle(pilot, lambda: "a_g·S = 0.3" in plain(app.query_one("#spectrum-info")))
            assert app.project is not None
            assert app.project.seismic.spectrum.type == "ntc2018"
            assert "a_g·S = 0.3" in plain(app.query_one("#spectrum-info", Static))
            await type_into(pilot, "#f-seismic-spectrum-ag-parameters-control", "2")
            assert row_error(app, ("seismic", "spectrum", "ag")) == (
                "expected a number in [0.001, 1.5], found 2"
            )

    run_async(body)


@pytest.mark.slow
def test_retrofit_table_add_duplicate_remove_and_errors(small_project: Path):
    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            await pilot.press("f6")
            editor = app.query_one(InterventionsEditor)
            await settle(pilot, lambda: app.focused is editor.table)
            assert len(editor.items) == 2
            await pilot.press("s")  # a sweep
            await settle(pilot, lambda: len(editor.items) == 3 and app.project is not None)
            assert "sweep" in editor.items[-1] and app.project is not None
            # GFRP × (centred, external) × 1‰: the external one repeats option 1 (dropped)
            assert len(app.project.expand_interventions()) == 3
            await pilot.press("d")  # duplicate: the same options, dropped on expansion
            await settle(pilot, lambda: len(editor.items) == 4)
            assert len(editor.items) == 4 and len(app.project.expand_interventions()) == 3
            await pilot.press("delete")
            await pilot.press("up")  # back to the CFRP option
            await settle(pilot, lambda: len(editor.items) == 3 and editor.selected == 1)
            ratio = next(r for r in editor.form_rows("option") if r.spec.path == ("ratio",)).control
            assert isinstance(ratio, Input) and ratio.value == "2"
            await type_into(pilot, f"#{ratio.id}", "25")
            row = next(r for r in editor.form_rows("option") if r.spec.path == ("ratio",))
            assert row.error == "expected a number in [0.001, 20], found 25"
            assert str(app.problems[0]) == (
                "interventions[1].ratio: expected a number in [0.001, 20], found 25"
            )
            await type_into(pilot, f"#{ratio.id}", "1.5")
            assert app.problems == []
            assert app.project.interventions[1].ratio == 1.5
            # FRP mass per metre of the option, updated as typed: 1.5‰·0.3 m·3 m·1550 kg/m³
            mass = f"{1.5e-3 * 0.3 * 3.0 * 1550:.2f}"
            await settle(pilot, lambda: str(editor.table.get_row_at(1)[7]) == mass)
            await pilot.press("a")  # new option from the table
            await pilot.pause()
            assert len(editor.items) == 3  # focus is in the form: 'a' was typed, not a binding
            editor.table.focus()
            await settle(pilot, lambda: app.focused is editor.table)
            await pilot.press("a")
            await settle(pilot, lambda: len(editor.items) == 4)

    run_async(body)


@pytest.mark.slow
def test_run_to_the_end_matches_batch_mode(small_project: Path, tmp_path: Path):
    async def body() -> dict[str, Any]:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            await pilot.press("ctrl+r")
            await after_workers(pilot, lambda: not app.running and app.outcome is not None)
            panel = app.query_one(RunPanel)
            assert [(c.done, c.total) for c in panel.case_counts()] == [(3, 3)] * 3
            assert app.outcome is not None and app.outcome.stats.computed == 9
            table = app.query_one(RankingTable)
            assert table.row_count == 3
            names = [str(table.get_row_at(i)[1]) for i in range(3)]
            results = app.outcome.results
            # rerun: every IDA comes from the cache, as in batch mode
            await pilot.press("ctrl+r")
            await after_workers(pilot, lambda: not app.running)
            assert app.outcome.stats.computed == 0 and app.outcome.stats.reused == 9
            # results: sorting, per record, history of the highlighted case
            await pilot.press("f9")
            await settle(pilot, lambda: app.focused is table)
            await pilot.press("right", "right", "right", "s")  # by FRP mass
            assert [app.outcome.results.cases[i].frp_mass for i in table.order] == sorted(
                c.frp_mass for c in app.outcome.results.cases
            )
            await pilot.press("enter")
            results_tabs = app.query_one("#results-tabs", TabbedContent)
            await settle(pilot, lambda: results_tabs.active == "res-records")
            # per record: the IDA curve's runs, and the case's scatter and fragility
            shown = plain(app.query_one("#case-summary", Static))
            assert "scatter over the records: median" in shown and "fragility" in shown
            records = app.query_one("#records-table", DataTable)
            case = app.outcome.results.cases[table.order[table.cursor_row]]
            assert str(records.get_row_at(0)[5]) == str(len(case.records[0].curve))
            await pilot.press("f10")
            await after_workers(pilot, lambda: history_shown(app))
            assert "under art-" in plain(app.query_one("#hist-info", Static))
        return {"names": names, "results": results}

    got = run_async(body)
    loaded = load_project(small_project)
    inputs = inputs_from_project(loaded.project, loaded.base_dir, small_project.name)
    batch, _ = run_assessment(inputs, tmp_path / "batch", pdf=False, jobs=1)
    tui = got["results"]
    assert set(got["names"]) == {c.name for c in batch.cases}
    assert got["names"][0] == batch.recommended
    assert tui.cases == batch.cases
    out = default_out_dir(small_project)
    on_disk = json.loads((out / "results.json").read_text())
    assert from_json((out / "results.json").read_text()).cases == tui.cases
    # the assessment's 9 IDAs and those of the model-convention variants of the best option
    variants = len(on_disk["sensitivity"]["rows"]) - 1  # the first row is a cached case
    assert len(list((out / CACHE_DIR).glob("*.json"))) == 9 + variants * len(on_disk["records"])
    assert (out / "report.pdf").read_bytes().startswith(b"%PDF")  # as `frp-assess run` writes
    # the inputs' digest, as `frp-assess run` records it (frp_assess/app/rerun.py): the file's
    # bytes and its records', so an unchanged `run` after the TUI's recomputes nothing
    records = [f.path for f in loaded.project.seismic.records.files or []]
    assert on_disk["inputs_digest"] == inputs_digest(small_project, records)
    assert tui.inputs_digest == on_disk["inputs_digest"]
    assert unchanged_run(small_project, out) is not None


@pytest.mark.slow
def test_cancel_a_run_keeps_the_ui_responsive(big_project: Path, monkeypatch: pytest.MonkeyPatch):
    """The cancel always lands mid-run: the run's first IDA stage is held at a gate (its
    runner waits on an event after the first finished pair) until the test has pressed
    escape, so the run cannot finish first however fast or slow the machine is (it waits for
    a state, never for a time)."""
    import threading

    import frp_assess.app.assessment as assessment

    first_pair, gate = threading.Event(), threading.Event()

    class GatedRunner(assessment.IdaRunner):
        def run(self, models, progress=None, on_pair=None, settings=None):  # type: ignore[no-untyped-def]
            def held(m_i: int, r_i: int) -> None:
                if on_pair is not None:
                    on_pair(m_i, r_i)
                first_pair.set()
                gate.wait()  # released once escape is pressed

            return super().run(models, progress, held, settings)

    monkeypatch.setattr(assessment, "IdaRunner", GatedRunner)

    async def body() -> None:
        app = FrpAssessApp(big_project, jobs=1)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            panel = app.query_one(RunPanel)
            derived = app.query_one("#derived-wall", Static)
            app.action_run()  # ctrl+r (the key itself is tested with the small project)
            assert app.running
            await settle(pilot, lambda: panel.last_stage == "ida" and first_pair.is_set())
            # the editor works while the run goes on: a new height, derived values follow
            app.action_tab(0)
            box = app.query_one("#f-wall-height-control", Input)
            box.value = "4"
            await settle(pilot, lambda: "4.289°" in plain(derived))
            assert app.running
            await pilot.press("escape")
            gate.set()
            await after_workers(pilot, lambda: not app.running)
            assert "cancelled" in plain(app.query_one("#run-state", Static))
            assert app.outcome is None
            done = sum(c.done for c in panel.case_counts())
            total = sum(c.total for c in panel.case_counts())
            assert total == 97 * 3 and 0 < done < total
            cache = default_out_dir(big_project) / CACHE_DIR
            assert len(list(cache.glob("*.json"))) >= done
            # still responsive: back to 3 m, typed
            await type_into(pilot, "#f-wall-height-control", "3")
            assert "5.711°" in plain(derived)

    try:
        run_async(body)
    finally:
        gate.set()  # never leave a worker thread waiting


@pytest.mark.slow
def test_save_and_reload_gives_the_same_project(small_project: Path, tmp_path: Path):
    """load -> save -> load gives the same project; saving keeps the file's comments and
    leaves an unchanged file byte for byte as it was."""
    text = "# North facade, survey of May\n" + small_project.read_text(encoding="utf-8").replace(
        "installation_per_metre: 100.0}", "installation_per_metre: 100.0}  # price list 2026"
    )
    small_project.write_text(text, encoding="utf-8")
    original = load_project(small_project).project

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            assert not app.modified()
            keys = plain(app.query_one("#keybar", Static))  # the footer
            for shown in ("^s Save", "^r Run", "^e Export", "? Help", "F2…F10 Tabs", "^q Quit"):
                assert shown.replace("? ", "?/F1 ") in keys
            await pilot.press("ctrl+s")  # unchanged: load -> save -> load
            await pilot.pause()
            assert load_project(small_project).project == original
            assert small_project.read_text(encoding="utf-8") == text
            await type_into(pilot, "#f-project-notes-control", "north facade: rocks")
            assert app.modified()
            await pilot.press("ctrl+s")
            await settle(pilot, lambda: not app.modified())
            again = load_project(small_project).project
            assert again == app.project
            assert again.project.notes == "north facade: rocks"
            saved = small_project.read_text(encoding="utf-8")
            assert "# North facade, survey of May" in saved and "}  # price list 2026" in saved

    run_async(body)


@pytest.mark.slow
def test_new_project_asks_for_a_file_name(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    monkeypatch.chdir(tmp_path)
    target = tmp_path / "sub" / "new wall.yaml"

    async def body() -> None:
        app = FrpAssessApp(None)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            # the template, shown field by field, gives back the template's project
            assert app.project == load_project_text(template_text(), "t.yaml").project
            assert len(app.project.expand_interventions()) == 19
            await pilot.press("ctrl+s")
            await settle(pilot, lambda: bool(app.screen.query("#path-input")))
            box = app.screen.query_one("#path-input", Input)
            box.value = str(target)
            await pilot.press("enter")
            error = app.screen.query_one("#path-error", Static)
            await settle(pilot, lambda: "no such directory" in plain(error))
            target.parent.mkdir()
            await pilot.press("enter")
            await settle(pilot, lambda: app.path == target)
            assert app.path == target and target.exists()
            assert load_project(target).project == app.project

    run_async(body)


@pytest.mark.slow
def test_export_pdf_and_help(small_project: Path, tmp_path: Path):
    export = tmp_path / "exported"

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            await pilot.press("ctrl+e")  # nothing to export yet: a message, no dialog
            await pilot.pause()
            assert not app.screen.query("#path-input")
            await pilot.press("ctrl+r")
            await after_workers(pilot, lambda: not app.running and app.outcome is not None)
            await pilot.press("ctrl+e")
            await settle(pilot, lambda: bool(app.screen.query("#path-input")))
            box = app.screen.query_one("#path-input", Input)
            # proposed: <stem>-export/ next to the project, never the results folder itself
            assert box.value == str(small_project.with_name("small-export"))
            assert box.value != str(default_out_dir(small_project))
            # the rule of `run --out`: the folder that holds the export must exist
            box.value = str(tmp_path / "missing" / "exported")
            await pilot.press("enter")
            error = app.screen.query_one("#path-error", Static)
            # (the message wraps at the dialog's width: compare it as one line)
            await settle(pilot, lambda: "missing does not exist" in " ".join(plain(error).split()))
            assert not (tmp_path / "missing").exists()
            box.value = str(export)
            await pilot.press("enter")
            await after_workers(pilot, lambda: (export / "results.json").exists())
            assert (export / "report.pdf").exists()
            assert (export / "report.docx").exists()  # as the prompt and the help say
            # help: F1 anywhere, ? outside free-text fields (also in a number field)
            thickness = app.query_one("#f-wall-thickness-control", Input)
            await pilot.press("f2")
            await settle(pilot, lambda: app.focused is thickness)
            await pilot.press("question_mark")
            await settle(pilot, lambda: isinstance(app.screen, HelpScreen))
            assert thickness.value == "0.3"
            await pilot.press("escape")
            await settle(pilot, lambda: not isinstance(app.screen, HelpScreen))
            await pilot.press("f1")
            await settle(pilot, lambda: isinstance(app.screen, HelpScreen))
            await pilot.press("escape")
            await settle(pilot, lambda: not isinstance(app.screen, HelpScreen))
            await pilot.press("f5")
            table = app.query_one("#materials-editor DataTable")
            await settle(pilot, lambda: app.focused is table)
            await pilot.press("question_mark")
            await settle(pilot, lambda: isinstance(app.screen, HelpScreen))

    run_async(body)
    assert (export / "report.pdf").read_bytes().startswith(b"%PDF")


@pytest.mark.slow
def test_invalid_file_opens_with_the_error_next_to_the_field(tmp_path: Path):
    path = tmp_path / "bad.yaml"
    path.write_text(
        "wall: {thickness: 0.3, height: 3.0, unit_weight: 40, mechanism: one-sided}\n"
        "seismic: {spectrum: {type: preset, name: A2}}\n",
        encoding="utf-8",
    )

    async def body() -> None:
        app = FrpAssessApp(path)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            assert row_error(app, ("wall", "unit_weight")) == (
                "expected a number in [5, 30], found 40"
            )
            await pilot.press("ctrl+r")
            log = app.query_one("#run-log")
            await settle(pilot, lambda: "cannot run: wall.unit_weight" in log_text(log))

    run_async(body)


@pytest.mark.slow
def test_quit_asks_when_there_are_unsaved_changes(small_project: Path):
    from frp_assess.tui.dialogs import ConfirmQuit

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            await type_into(pilot, "#f-wall-height-control", "4")
            await pilot.press("ctrl+q")
            await settle(pilot, lambda: isinstance(app.screen, ConfirmQuit))
            await pilot.press("escape")  # stay
            await settle(pilot, lambda: not isinstance(app.screen, ConfirmQuit))
            assert app.return_code is None
            await pilot.press("ctrl+q", "d")  # discard and quit
            await settle(pilot, lambda: app.return_code == 0)
        assert load_project(small_project).project.wall.height == 3.0  # not saved

    run_async(body)


@pytest.mark.slow
def test_opening_a_project_shows_its_last_run(small_project: Path):
    """Results are not lost between sessions: opening a project that was run before shows
    that run's ranking (rebuilt from the cache, nothing recomputed or rewritten), and the
    time-history viewer works on it."""
    loaded = load_project(small_project)
    inputs = inputs_from_project(loaded.project, loaded.base_dir, small_project.name)
    out = default_out_dir(small_project)
    stored, _ = run_assessment(inputs, out, pdf=False, jobs=2, created="2026-01-02")
    stamp = (out / "results.json").stat().st_mtime_ns

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await after_workers(pilot, lambda: app.outcome is not None)
            assert app.outcome.stats.computed == 0 and not app.running
            assert app.outcome.results.cases == stored.cases
            assert app.outcome.results.created == "2026-01-02"
            assert app.query_one(RankingTable).row_count == 3
            await pilot.press("f10")
            await after_workers(pilot, lambda: history_shown(app))

    run_async(body)
    assert (out / "results.json").stat().st_mtime_ns == stamp


@pytest.mark.slow
def test_a_late_focus_message_does_not_switch_the_tab(small_project: Path):
    """The tab is changed on purpose only: the focus message of a field of the Wall tab that
    is handled after the user went to another tab leaves that tab shown (and the focus
    follows the tab shown)."""

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            wall = app.query_one("#tab-wall", TabPane)
            assert app.focused is not None and wall in app.focused.ancestors
            tabs = app.query_one("#tabs", TabbedContent)
            tabs.active = "tab-history"  # as F10, before the focus has left the Wall tab
            wall.post_message(TabPane.Focused(wall))  # the late message
            await settle(pilot, lambda: app.focused is None or wall not in app.focused.ancestors)
            assert tabs.active == "tab-history"

    run_async(body)


@pytest.mark.slow
def test_building_block_switched_on_validated_and_saved(small_project: Path):
    """A wall above the ground floor: the Wall tab's building fields, the loader's located
    message under Z, and the block saved into the file (and left out when switched off)."""

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            assert app.project is not None and app.project.building is None
            mode = app.query_one("#f-building-mode-control", Select)
            mode.value = "on"
            await settle(pilot, lambda: app.project is not None and bool(app.project.building))
            assert app.project is not None and app.project.building is not None
            assert app.project.building.wall_base == 9.0  # the template's values
            await type_into(pilot, "#f-building-wall-base-on-control", "12")
            assert row_error(app, ("building", "wall_base")) == (
                "expected 0 <= Z < height H_b = 10 m, found 12"
            )
            assert "Wall ✗" in str(app.query_one("#tabs", TabbedContent).get_tab("tab-wall").label)
            await type_into(pilot, "#f-building-wall-base-on-control", "6")
            assert app.problems == []
            await pilot.press("ctrl+s")
            await settle(pilot, lambda: not app.modified())
            saved = load_project(small_project).project.building
            assert saved is not None and (saved.height, saved.storeys, saved.wall_base) == (
                10.0,
                3,
                6.0,
            )
            mode.value = "off"
            await settle(pilot, lambda: app.project is not None and app.project.building is None)
            await pilot.press("ctrl+s")
            await settle(pilot, lambda: not app.modified())
            assert load_project(small_project).project.building is None

    run_async(body)
