"""Nothing lost: what the editor has no field for (the ``bars:`` block...) is carried from the
file into the data, so that a run started from the TUI uses it and a save writes it back."""

from __future__ import annotations

from pathlib import Path

import pytest
from textual.widgets import Input, Select

from frp_assess.assess.from_project import bar_settings_of
from frp_assess.config import load_project
from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.core.editor_state import without_paths
from frp_assess.tui.interventions import InterventionsEditor
from frp_assess.tui.materials import MaterialsEditor
from tests.tui.conftest import SMALL, after_workers, run_async, settle, show_tab
from tests.tui.test_app import SIZE, type_into

#: a bars block with every key away from its default, as an engineer writes it
BARS = """\
bars:                      # as built on site
  exposure: internal       # behind the plaster
  design_values: false
  whole_bars: false
  min_spacing: 0.2         # m
  max_spacing: 0.8         # m
  catalogue:
    - {material: GFRP, diameter: 11.0, area: 95.0, source: data sheet X}
  anchorage: {hole_clearance: 6.0, bond_bar: 9.0, bond_masonry: 0.5}
"""


def bars_lines(text: str) -> list[str]:
    """The lines of the ``bars:`` block of a project file (to the end of the file)."""
    lines = text.splitlines()
    return lines[lines.index(next(x for x in lines if x.startswith("bars:"))) :]


def test_without_paths_removes_keys_and_the_blocks_they_empty():
    data = {
        "analysis": {"pivot": "edge", "ida": {"tolerance": 0.01}},
        "bars": {"exposure": "internal"},
        "costs": {},
    }
    out = without_paths(data, [("analysis", "ida", "tolerance"), ("bars", "nope"), ("x", "y")])
    assert out == {"analysis": {"pivot": "edge"}, "bars": {"exposure": "internal"}, "costs": {}}
    assert without_paths(data, [("analysis", "pivot"), ("analysis", "ida", "tolerance")]) == {
        "bars": {"exposure": "internal"},
        "costs": {},  # empty in the file: kept (only what a removal empties goes)
    }
    assert data["analysis"]["ida"] == {"tolerance": 0.01}  # a copy: the input is untouched
    assert without_paths(["not", "a", "mapping"], [("a",)]) == {}


@pytest.mark.slow
def test_save_keeps_the_bars_block_as_written(tmp_path: Path):
    path = tmp_path / "wall.yaml"
    path.write_text(SMALL + BARS, encoding="utf-8")
    before = load_project(path).project

    async def body() -> None:
        app = FrpAssessApp(path)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            assert app.project is not None and app.project.bars == before.bars
            assert not app.modified()
            await type_into(pilot, "#f-project-notes-control", "north facade")
            assert app.modified()
            await pilot.press("ctrl+s")
            await settle(pilot, lambda: not app.modified())

    run_async(body)
    text = path.read_text(encoding="utf-8")
    assert bars_lines(text) == bars_lines(SMALL + BARS)  # comments and layout too
    after = load_project(path).project
    assert after.bars == before.bars and after.project.notes == "north facade"


@pytest.mark.slow
def test_other_blocks_of_a_variant_go_when_the_variant_changes(tmp_path: Path):
    """Carrying the file's keys does not resurrect a block the user switched off."""
    path = tmp_path / "wall.yaml"
    path.write_text(
        SMALL + "design: {materials: [GFRP], positions: [external]}\n" + BARS, encoding="utf-8"
    )

    async def body() -> None:
        app = FrpAssessApp(path)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            assert app.project is not None and app.project.design is not None
            await show_tab(pilot, "tab-analysis")
            app.query_one("#f-design-mode-control", Select).value = "off"
            await settle(pilot, lambda: app.project is not None and app.project.design is None)
            await pilot.press("ctrl+s")
            await settle(pilot, lambda: not app.modified())

    run_async(body)
    saved = load_project(path).project
    assert saved.design is None and saved.bars.exposure == "internal"


@pytest.mark.slow
def test_a_run_from_the_tui_uses_the_projects_bars(tmp_path: Path):
    """With ``whole_bars: false`` the model takes the ratios asked (1 and 2 ‰); with the
    default whole bars it would take the installed ones (1.005... and 2.01... ‰ here)."""
    path = tmp_path / "wall.yaml"
    path.write_text(SMALL + BARS, encoding="utf-8")
    loaded = load_project(path).project

    async def body() -> None:
        app = FrpAssessApp(path)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            await pilot.press("ctrl+r")
            await after_workers(pilot, lambda: not app.running and app.outcome is not None)
            assert app.outcome is not None
            assert app.outcome.inputs.bars == bar_settings_of(loaded.bars)
            assert [c.ratio for c in app.outcome.results.options] == [1.0, 2.0]

    run_async(body)


@pytest.mark.slow
def test_fields_for_pivot_strength_fc_diameter_and_design_strain(tmp_path: Path):
    """The keys of issue 16 have fields: a file's values show in them, edits reach the project
    and the save (every value below is away from the schema's default)."""
    path = tmp_path / "wall.yaml"
    path.write_text(
        SMALL.replace("mechanism: one-sided}", "mechanism: one-sided, compressive_strength: 2.4}")
        + "analysis: {pivot: edge}\ncode_check: {fc_in_ida: false}\n",
        encoding="utf-8",
    )

    async def body() -> None:
        app = FrpAssessApp(path)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            q = app.query_one
            assert q("#f-wall-compressive-strength-control", Input).value == "2.4"
            await type_into(pilot, "#f-wall-compressive-strength-control", "3.5")
            await show_tab(pilot, "tab-analysis")
            assert q("#f-analysis-pivot-control", Select).value == "edge"
            assert q("#f-code-check-fc-in-ida-control", Select).value is False
            q("#f-analysis-pivot-control", Select).value = "crushing"
            q("#f-code-check-fc-in-ida-control", Select).value = True
            await settle(
                pilot, lambda: app.project is not None and app.project.code_check.fc_in_ida
            )
            # the first option's bar diameter, typed in the Retrofits form
            await show_tab(pilot, "tab-retrofits")
            editor = q(InterventionsEditor)
            diameter = next(r for r in editor.form_rows("option") if r.spec.path == ("diameter",))
            await type_into(pilot, f"#{diameter.control.id}", "12")
            # GFRP's characteristic strain and fibre, in the Materials form
            await show_tab(pilot, "tab-materials")
            materials = q(MaterialsEditor)
            assert materials.items[0] == "GFRP" and materials.selected == 0
            rows = {r.spec.path: r for r in materials.form_rows("material")}
            await type_into(pilot, f"#{rows[('characteristic_strain',)].control.id}", "0.014")
            rows[("fibre",)].control.value = "basalt"
            await settle(
                pilot,
                lambda: (
                    app.project is not None
                    and app.project.materials.get("GFRP") is not None
                    and app.project.materials["GFRP"].fibre == "basalt"
                ),
            )
            await pilot.press("ctrl+s")
            await settle(pilot, lambda: not app.modified())

    run_async(body)
    saved = load_project(path).project
    assert saved.wall.compressive_strength == 3.5
    assert saved.analysis.pivot == "crushing" and saved.code_check.fc_in_ida is True
    assert saved.interventions[0].diameter == 12.0  # type: ignore[union-attr]
    gfrp = saved.materials["GFRP"]
    assert (gfrp.characteristic_strain, gfrp.fibre) == (0.014, "basalt")
