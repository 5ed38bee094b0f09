"""`frp-assess run` of a building file (issue 41 item 2): every wall assessed exactly as a
one-wall project of that wall, each cached on its own (an edit of one wall recomputes that
wall only), `--wall NAME`, and the folder rules for the building's own files."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
import yaml

from frp_assess.app.building_run import load_building_inputs, run_building
from frp_assess.cli import main
from tests.cli.outputs_helpers import tree

FIXTURE = Path(__file__).parents[1] / "fixtures" / "building-small.yaml"
CREATED = "2026-01-01"
SLUGS = ("facciata-sud-piano-terra", "timpano-est", "parapetto")


@pytest.fixture(scope="module")
def building_run(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The small building run once (no reports: the report is tested on its own)."""
    root = tmp_path_factory.mktemp("building")
    project = root / "building.yaml"
    shutil.copyfile(FIXTURE, project)
    out = root / "out"
    argv = ["run", str(project), "--out", str(out), "--no-pdf", "--created", CREATED]
    assert main(argv) == 0
    return out


def _without_origin(text: str) -> dict[str, object]:
    """results.json without what names the file it came from (input_file, inputs_digest)."""
    data = json.loads(text)
    data.pop("input_file")
    data.pop("inputs_digest", None)
    return data


def _one_wall_project(index: int) -> dict[str, object]:
    """The one-wall project of the building's wall ``index``, written by hand from the file:
    the shared blocks, the wall's keys under wall:, its own building:/interventions:."""
    data = yaml.safe_load(FIXTURE.read_text(encoding="utf-8"))
    item = dict(data.pop("walls")[index])
    name = item.pop("name")
    for key in ("building", "interventions"):
        if key in item:
            data[key] = item.pop(key)
    data["wall"] = item
    data["project"]["name"] = f"{data['project']['name']} — {name}"
    return data


@pytest.mark.parametrize("index", [0, 1])  # loads and the shared option; own floor and options
def test_each_wall_equals_its_one_wall_project(
    building_run: Path, tmp_path: Path, index: int
) -> None:
    project = tmp_path / "wall.yaml"
    project.write_text(yaml.safe_dump(_one_wall_project(index), allow_unicode=True), "utf-8")
    out = tmp_path / "out"
    assert main(["run", str(project), "--out", str(out), "--no-pdf", "--created", CREATED]) == 0
    wall = building_run / "walls" / SLUGS[index]
    alone = _without_origin((out / "results.json").read_text(encoding="utf-8"))
    assert _without_origin((wall / "results.json").read_text(encoding="utf-8")) == alone
    for name in ("results.csv", "spectra.csv"):
        assert (wall / name).read_bytes() == (out / name).read_bytes()
    assert sorted(p.name for p in (wall / "records").iterdir()) == sorted(
        p.name for p in (out / "records").iterdir()
    )


def test_the_building_folder(building_run: Path) -> None:
    names = {p.name for p in building_run.iterdir() if not p.name.startswith(".")}
    assert names == {"results.json", "results.csv", "walls"}  # --no-pdf: no reports
    assert sorted(p.name for p in (building_run / "walls").iterdir()) == sorted(SLUGS)
    data = json.loads((building_run / "results.json").read_text(encoding="utf-8"))
    assert data["kind"] == "building" and data["building_schema_version"] == 1
    assert [w["folder"] for w in data["walls"]] == [f"walls/{s}" for s in SLUGS]
    # the CSV: one row per wall and case (the unreinforced wall and each option)
    rows = (building_run / "results.csv").read_text(encoding="utf-8-sig").splitlines()
    cases = [
        len(json.loads((building_run / "walls" / s / "results.json").read_text())["cases"])
        for s in SLUGS
    ]
    assert len(rows) == 1 + sum(cases)


def test_an_edit_of_one_wall_recomputes_that_wall_only(building_run: Path, tmp_path: Path) -> None:
    """The cache key is the wall's model and the record (assess/cache.py), and each wall has
    its own cache in its folder: the parapet made taller recomputes its IDAs alone."""
    out = tmp_path / "out"
    shutil.copytree(building_run, out)
    project = tmp_path / "building.yaml"
    text = FIXTURE.read_text(encoding="utf-8")
    assert text.count("    height: 1.0\n") == 1
    project.write_text(text.replace("    height: 1.0\n", "    height: 1.2\n"), "utf-8")
    building = load_building_inputs(project, warn=None)
    run = run_building(building, out, jobs=2, created=CREATED, pdf=False, reuse=False)
    stats = {o.wall.name: (o.stats.computed, o.stats.reused) for o in run.walls}
    records = 2
    assert stats["Facciata sud, piano terra"] == (0, 2 * records)  # unreinforced + 1 option
    assert stats["Timpano est"] == (0, 2 * records)
    assert stats["Parapetto"] == (2 * records, 0)
    assert run.building is not None
    assert [w.height for w in run.building.walls] == [3.5, 2.5, 1.2]
    # run again as `run` does (without --created): every wall's folder holds the run of its
    # inputs as they are now, so none runs; then an edit of the gable runs the gable alone
    again = run_building(building, out, jobs=2, pdf=False)
    assert [o.unchanged for o in again.walls] == [True, True, True]
    assert (again.computed, again.reused) == (0, 0)
    text = project.read_text(encoding="utf-8").replace("length: 7.0", "length: 7.5")
    project.write_text(text, "utf-8")
    edited = run_building(load_building_inputs(project, warn=None), out, jobs=2, pdf=False)
    assert [o.unchanged for o in edited.walls] == [True, False, True]
    gable = edited.walls[1]
    # 7.5 m holds 60 bars per face at the same spacing as 56 on 7 m: the same ratio and model
    assert gable.stats.computed == 0 and gable.stats.reused == 2 * records
    assert gable.results.wall.length == 7.5


def test_one_wall_by_name(building_run: Path, tmp_path: Path) -> None:
    project = tmp_path / "building.yaml"
    shutil.copyfile(FIXTURE, project)
    out = tmp_path / "out"
    argv = ["run", str(project), "--out", str(out), "--no-pdf", "--created", CREATED]
    assert main([*argv, "--wall", "Timpano est"]) == 0
    assert [p.name for p in (out / "walls").iterdir()] == ["timpano-est"]
    assert not (out / "results.json").exists()  # the building's summary needs every wall
    ran = _without_origin((out / "walls/timpano-est/results.json").read_text(encoding="utf-8"))
    whole = building_run / "walls/timpano-est/results.json"
    assert ran == _without_origin(whole.read_text(encoding="utf-8"))


def test_an_unknown_wall_is_one_line_listing_the_names(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "out"
    assert main(["run", str(FIXTURE), "--out", str(out), "--wall", "Timpano"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert "no wall named 'Timpano'" in err and "'Timpano est'" in err and "'Parapetto'" in err
    assert not out.exists()
    one_wall = Path(__file__).parents[2] / "projects" / "facade-laquila.yaml"
    assert main(["run", str(one_wall), "--out", str(out), "--wall", "x"]) == 2
    assert "expected a building file" in capsys.readouterr().err


def test_a_wall_s_bad_value_writes_nothing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    project = tmp_path / "building.yaml"
    text = FIXTURE.read_text(encoding="utf-8").replace("    height: 2.5\n", "    height: 0.2\n")
    project.write_text(text, "utf-8")
    out = tmp_path / "out"
    assert main(["run", str(project), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "walls[1].height" in err, err
    assert not out.exists()


def test_a_users_file_in_the_building_folder_is_never_replaced(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "out"
    out.mkdir()
    (out / "results.csv").write_bytes(b"the user's own table")
    before = tree(out)
    assert main(["run", str(FIXTURE), "--out", str(out), "--no-pdf"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "results.csv" in err, err
    assert tree(out) == before


def test_the_summary_s_numbers_are_each_wall_s_results(building_run: Path) -> None:
    """Every number of the building's results.json is the one its wall's results.json holds
    (the summary copies, it never computes anew): α₀ and a₀* of the code check, ζ_E of each
    check of the unreinforced wall and of the proposed option, the verdicts, the proposal's
    FRP mass and cost; the totals are their sums and the governing wall the smallest margin."""
    building = json.loads((building_run / "results.json").read_text(encoding="utf-8"))
    margins = {}
    mass = cost = 0.0
    for row in building["walls"]:
        wall = json.loads((building_run / row["folder"] / "results.json").read_text("utf-8"))
        assert row["alpha0"] == wall["code_check"]["alpha0"]
        assert row["a0_star"] == wall["code_check"]["a0_star"]
        checks = {c["case"]: c for c in wall["kinematic_checks"]["cases"]}
        cases = {c["name"]: c for c in wall["cases"]}
        proposed = wall["recommended"] if wall["retrofit_required"] else None
        assert row["proposed"] == proposed
        for key, name in (("unreinforced", "Unreinforced"), ("proposed_checks", proposed)):
            if name is None:
                assert row[key] is None
                continue
            z, c = row[key], checks[name]
            assert z["linear"] == c["linear"]["zeta_e"]
            assert z["nonlinear_slv"] == c["slv"]["zeta_e"]
            assert z["nonlinear_slc"] == c["slc"]["zeta_e"]
            assert z["time_history_slv"] == c["time_history"]["margin"]
            assert z["time_history_slc"] == c["time_history_slc"]["margin"]
            assert z["ida"] == c["ida"]["zeta_e"]
            assert z["governing_check"] == cases[name]["governing_check"]
            assert z["governing_margin"] == cases[name]["governing_margin"]
        before = "passes" if cases["Unreinforced"]["passes"] else "fails"
        assert row["verdict_before"] == before
        if proposed is not None:
            assert row["frp_mass"] == cases[proposed]["frp_mass"]
            assert row["frp_cost"] == cases[proposed]["frp_cost"]
            built = cases[proposed]["as_built"]
            assert row["as_built"] == built["note"]
            assert {k: built[k] for k in row["bars"]} == row["bars"]
            mass += cases[proposed]["frp_mass"]
            cost += cases[proposed]["frp_cost"]
        margins[row["name"]] = cases["Unreinforced"]["governing_margin"]
    totals = building["totals"]
    assert totals["frp_mass"] == pytest.approx(mass) and totals["frp_cost"] == pytest.approx(cost)
    assert totals["governing_wall"] == min(margins, key=lambda n: margins[n])
    assert totals["walls_failing"] == sum(w["verdict_before"] == "fails" for w in building["walls"])


def test_report_of_the_building_folder_points_to_the_walls(
    building_run: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["report", str(building_run), "--out", str(building_run.parent / "r.pdf")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "is a building's summary" in err and "walls/" in err


def test_a_users_file_in_a_wall_s_folder_or_a_link_for_walls_is_refused(
    building_run: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A wall's folder follows a results folder's rules (checked before any work), and the
    walls/ folder itself is never a link or a file."""
    out = tmp_path / "out"
    shutil.copytree(building_run, out)
    (out / "walls" / "parapetto" / "results.csv").write_bytes(b"the user's own table")
    before = tree(out)
    assert main(["run", str(FIXTURE), "--out", str(out), "--no-pdf"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "parapetto" in err and "results.csv" in err, err
    assert tree(out) == before
    other = tmp_path / "other"
    other.mkdir()
    linked = tmp_path / "linked"
    linked.mkdir()
    (linked / "walls").symlink_to(other)
    assert main(["run", str(FIXTURE), "--out", str(linked), "--no-pdf"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "walls" in err and "link" in err, err
    assert list(other.iterdir()) == []


@pytest.mark.parametrize(
    ("text", "building"),
    [
        ("walls:\n  - name: a\n", True),
        ("project: {name: x}\nwalls: []\n", True),
        ("\ufeff'walls' : []\n", True),
        ("project:\n  notes: |\n    walls: many\nwall: {}\n", False),  # a block scalar's text
        ("# walls:\nwall: {}\n", False),  # the template's comment
        ('# c\n{"project": {"name": "x"}, "walls": []}\n', True),  # flow style: parsed
        ('{"project": {"notes": "walls: x"}, "wall": {}}\n', False),
    ],
)
def test_run_tells_a_building_file_before_importing_the_schema(
    tmp_path: Path, text: str, building: bool
) -> None:
    from frp_assess.app.building_file import is_building_file

    path = tmp_path / "f.yaml"
    path.write_text(text, encoding="utf-8")
    assert is_building_file(path) is building
    assert is_building_file(path, "a wall") is True  # --wall: a building is expected
