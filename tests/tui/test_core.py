"""The headless parts of the TUI split out of the app: opening a file, the figures shown
next to the fields, and which tab edits which key."""

from __future__ import annotations

from pathlib import Path

import pytest

from frp_assess.api import TEMPLATE_NAME
from frp_assess.assess.from_project import material_of
from frp_assess.assess.inputs import CostSettings
from frp_assess.assess.quantities import frp_quantity
from frp_assess.config import load_project_text, project_data
from frp_assess.tui.core.opening import opening_data
from frp_assess.tui.core.project_info import (
    option_rows,
    record_count,
    records_summary,
    retrofits_summary,
)
from frp_assess.tui.core.tabs import TABS, tab_of, tab_title
from tests.tui.conftest import SMALL


def test_opening_a_valid_file_gives_the_loaders_data(small_project: Path):
    data, message = opening_data(small_project, None, small_project.parent)
    project = load_project_text(SMALL, "s.yaml").project
    assert message == "" and data == project_data(project)


def test_opening_an_invalid_file_keeps_its_data_and_says_why(tmp_path: Path):
    path = tmp_path / "bad.yaml"
    path.write_text(SMALL.replace("thickness: 0.3", "thickness: 4.0"), encoding="utf-8")
    data, message = opening_data(path, None, tmp_path)
    assert data["wall"]["thickness"] == 4.0
    assert message.startswith(f"{path}:") and "thickness" in message


def test_opening_a_file_that_is_not_yaml_opens_empty(tmp_path: Path):
    path = tmp_path / "bad.yaml"
    path.write_text("wall: [1, 2\n", encoding="utf-8")
    data, message = opening_data(path, None, tmp_path)
    assert data == {} and message.startswith(f"{path}:")


def test_a_new_file_opens_the_template_named_after_it(tmp_path: Path):
    data, message = opening_data(tmp_path / "east_wall.yaml", None, tmp_path)
    assert message == "" and data["project"]["name"] == "east wall"
    data, _ = opening_data(None, None, tmp_path)
    assert data["project"]["name"] == TEMPLATE_NAME


def test_option_rows_are_the_quantities_of_the_expanded_options():
    project = load_project_text(SMALL, "s.yaml").project
    rows = option_rows(project)
    options = project.expand_interventions()
    assert [r.name for r in rows] == [str(o.name) for o in options]
    w, table = project.wall, project.material_table()
    costs = CostSettings(str(project.costs.currency), project.costs.installation_per_metre)
    for r, o in zip(rows, options, strict=True):
        q = frp_quantity(
            w.thickness, w.height, w.length, material_of(table[o.material]), o.position,
            o.ratio, costs,
        )  # fmt: skip
        assert (r.mass_per_m, r.mass, r.cost) == (q.mass_per_m, q.mass, q.cost)


def test_summaries_count_cases_records_and_idas():
    project = load_project_text(SMALL, "s.yaml").project
    assert record_count(project) == 3
    assert "2 after expanding sweeps" in retrofits_summary(project)
    assert "3 cases × 3 records = 9 IDAs" in retrofits_summary(project)
    assert retrofits_summary(None).startswith("Retrofit options (")
    text, rule = records_summary(project)
    assert text.startswith("3 artificial records of 14 s at dt = 0.01 s (1401 samples)")
    assert rule.startswith("least favourable record")


@pytest.mark.parametrize(
    ("path", "tab"),
    [
        (("project", "name"), "tab-wall"),
        (("wall", "height"), "tab-wall"),
        (("seismic", "spectrum", "ag"), "tab-site"),
        (("seismic", "t1"), "tab-site"),
        (("seismic", "records", "files", 0, "path"), "tab-records"),
        (("materials", "X", "density"), "tab-materials"),
        (("interventions", 2, "ratio"), "tab-retrofits"),
        (("analysis", "ida", "tolerance"), "tab-analysis"),
        (("costs", "currency"), "tab-analysis"),
        ((), "tab-wall"),
    ],
)
def test_each_key_is_edited_in_its_tab(path, tab):
    assert tab_of(path) == tab
    assert tab_title(tab) in dict(TABS).values()
