"""The application service's own entry points (frp_assess.app): checking a file, preparing and
running a project as the TUI does, the previews.  The pipeline itself is tested through
frp_assess.api (tests/test_api.py, tests/assess) and the interfaces (tests/cli, tests/tui)."""

from __future__ import annotations

import math
import threading
from pathlib import Path
from typing import Any, cast

import pytest
import yaml

from frp_assess.app.assessment import prepare_run, run_prepared
from frp_assess.app.preview import frp_mass_per_metre, wall_derived
from frp_assess.app.project import (
    CheckedBuilding,
    CheckedProject,
    CheckedStudy,
    check_file,
    ensure_project_file,
    load_project_text,
)
from frp_assess.app.report import export_folder_problem, export_run
from frp_assess.assess.wall_model import case_design_strength
from frp_assess.config.library import FRP_MATERIALS
from frp_assess.config.schema import WallSpec
from frp_assess.errors import Cancelled, InputError
from tests.study.conftest import TINY
from tests.tui.conftest import SMALL


def test_check_file_tells_a_project_from_a_study(tmp_path: Path) -> None:
    project = tmp_path / "small.yaml"
    project.write_text(SMALL, encoding="utf-8")
    checked = check_file(project)
    assert isinstance(checked, CheckedProject)
    assert checked.loaded.project.wall.thickness == 0.3
    study = tmp_path / "tiny.yaml"
    study.write_text(yaml.safe_dump(TINY), encoding="utf-8")
    got = check_file(study)
    assert isinstance(got, CheckedStudy) and got.study.name == "tiny"
    with pytest.raises(InputError, match="is a study file"):
        ensure_project_file(study)
    ensure_project_file(project)  # a project passes
    building = Path(__file__).parent / "fixtures" / "building-small.yaml"
    assert isinstance(check_file(building), CheckedBuilding)
    ensure_project_file(building)  # the TUI edits a building wall by wall
    repeated = tmp_path / "repeated.yaml"
    text = building.read_text(encoding="utf-8").replace("name: Parapetto", "name: Timpano est")
    repeated.write_text(text, encoding="utf-8")
    with pytest.raises(InputError, match=r"walls\[2\]\.name: 'Timpano est' is already the name"):
        ensure_project_file(repeated)  # a list of walls the TUI cannot show: one line


def test_prepare_run_reports_the_records_stage_and_a_cancelled_run_writes_nothing(
    tmp_path: Path,
) -> None:
    project = load_project_text(SMALL, "small.yaml").project
    stages: list[tuple[str, int, int]] = []
    prepared = prepare_run(
        project, tmp_path, "small.yaml", progress=lambda s, d, n: stages.append((s, d, n))
    )
    assert stages == [("records", 0, 1), ("records", 1, 1)]
    assert prepared.inputs.case_names() == ["Unreinforced", "GFRP external 1‰", "CFRP centred 2‰"]
    stop = threading.Event()
    stop.set()
    out = tmp_path / "out"
    with pytest.raises(Cancelled):
        run_prepared(prepared, out, cancel=stop, jobs=1)
    assert not out.exists()


def test_a_tui_run_refuses_a_folder_with_a_users_file_before_any_work(tmp_path: Path) -> None:
    """The TUI's run (run_prepared) checks its results folder as ``run --out`` does (issue 36
    item 1): a user's results.csv there is refused before any IDA, and left as it was."""
    project = load_project_text(SMALL, "small.yaml").project
    prepared = prepare_run(project, tmp_path, "small.yaml")
    out = tmp_path / "small-results"
    out.mkdir()
    (out / "results.csv").write_text("mine", encoding="utf-8")
    with pytest.raises(InputError, match="results.csv is not a file frp-assess wrote"):
        run_prepared(prepared, out, cancel=threading.Event(), jobs=1)
    assert sorted(p.name for p in out.iterdir()) == ["results.csv"]  # no .cache, no .lock
    assert (out / "results.csv").read_text(encoding="utf-8") == "mine"


def test_export_follows_the_missing_parent_rule_of_run_out(tmp_path: Path) -> None:
    """The TUI's export folder is checked as ``run --out`` is (frp_assess/output_set.py,
    "Missing parent folder"): a new folder is fine, a new folder under a missing one is
    refused naming the missing folder, and nothing is created; a file is refused."""
    assert export_folder_problem(tmp_path / "new") is None
    assert export_folder_problem(tmp_path) is None
    deep = tmp_path / "a" / "b" / "export"
    problem = export_folder_problem(deep)
    assert problem is not None and f"{tmp_path / 'a' / 'b'} does not exist" in problem
    (tmp_path / "file").write_text("x")
    assert "is a file" in (export_folder_problem(tmp_path / "file") or "")
    # the export itself refuses before it looks at the run (here: no run at all)
    with pytest.raises(InputError) as info:
        export_run(cast(Any, None), deep)
    assert info.value.key == "export" and "does not exist" in info.value.message
    assert not (tmp_path / "a").exists()


def test_previews_are_the_closed_forms() -> None:
    """About the edge: α = atan(B/H), R = ½·√(B² + H²), a_RM = tan α = B/H [g]; about the
    crushing pivot a_RM = (B − x_W)/H with x_W = W/(0.85·f_d), W = w·B·H per metre
    (docs/model.md §1.1); FRP mass per metre = ρ·B·H·density, twice for external bars (one
    layer per face)."""
    spec = WallSpec.model_validate(
        {"thickness": 0.3, "height": 3.0, "unit_weight": 18.0, "mechanism": "one-sided",
         "masonry": "solid-brick-lime-mortar"}
    )  # fmt: skip
    edge = wall_derived(spec, pivot="edge")
    assert edge.alpha == pytest.approx(math.atan(0.1))
    assert edge.R == pytest.approx(0.5 * math.hypot(0.3, 3.0))
    assert edge.a_rm == pytest.approx(0.1) and edge.depth == 0.0
    f_d = case_design_strength("solid-brick-lime-mortar", "LC1") * 1e6  # [Pa]
    x_w = 18e3 * 0.3 * 3.0 / (0.85 * f_d)  # [m]
    crushing = wall_derived(spec, pivot="crushing", level="LC1")
    assert crushing.depth == pytest.approx(x_w)
    assert crushing.a_rm == pytest.approx((0.3 - x_w) / 3.0)
    gfrp = FRP_MATERIALS["GFRP"]
    one_face = 1e-3 * 0.3 * 3.0 * gfrp.density  # ρ = 1 ‰ of B per metre, over H
    assert frp_mass_per_metre(0.3, 3.0, gfrp, "centred", 1.0) == pytest.approx(one_face)
    assert frp_mass_per_metre(0.3, 3.0, gfrp, "external", 1.0) == pytest.approx(2 * one_face)
