"""The TUI's pure parts: field text <-> data, validation messages, derived values, plots."""

from __future__ import annotations

import copy
import math

import pytest
import yaml
from rich.text import Text

from frp_assess.api import prepare_records, run_assessment
from frp_assess.assess.from_project import inputs_from_project
from frp_assess.config import load_project_text, project_data, validate_data
from frp_assess.dynamics import Wall
from frp_assess.errors import InputError
from frp_assess.tui.core.editor_state import (
    MISSING,
    format_value,
    frp_mass_per_m,
    material_table,
    parse_key,
    parse_list,
    parse_scalar,
    record_file_problem,
    spectrum_preview,
    validate_edit,
    wall_derived,
)
from frp_assess.tui.core.progress import CaseProgress
from frp_assess.tui.plots import BRAILLE_BASE, Rule, Series, data_range, render_plot, tick
from tests.tui.conftest import SMALL


def small_data() -> dict:
    return yaml.safe_load(SMALL)


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("0.4", 0.4),
        ("7", 7),
        ("1e-3", 0.001),
        ("abc", "abc"),
        ("0.4 m", "0.4 m"),
        ("yes", True),
        ("", MISSING),
        ("  ", MISSING),
        ("[1,", "[1,"),
        ("energy", "energy"),
    ],
)
def test_parse_scalar_reads_like_the_yaml_loader(text, value):
    assert parse_scalar(text) == value or (value is MISSING and parse_scalar(text) is MISSING)


@pytest.mark.parametrize("value", [0.395, 0.1 + 0.2, 1e-5, 3.0, 100.0, 1e20, 7, -2.5, 0.005])
def test_format_then_parse_gives_the_same_number(value):
    assert parse_scalar(format_value(value)) == value
    assert not format_value(3.0).endswith(".0")


def test_lists():
    assert parse_list("GFRP, CFRP") == ["GFRP", "CFRP"]
    assert parse_list("[1, 2.5]") == [1, 2.5]
    assert parse_list("") == []
    assert parse_list("1, [") == "1, ["
    assert format_value([1.0, 2.5]) == "1, 2.5"


def test_parse_key_inverts_format_path():
    assert parse_key("seismic.records.files[0].path") == ("seismic", "records", "files", 0, "path")
    assert parse_key("interventions[2].sweep.ratio[1]") == (
        "interventions",
        2,
        "sweep",
        "ratio",
        1,
    )


def _loader_error(data: dict) -> InputError:
    with pytest.raises(InputError) as info:
        validate_data(data)
    return info.value


@pytest.mark.parametrize(
    "change",
    [
        lambda d: d["wall"].__setitem__("thickness", 3.5),
        lambda d: d["wall"].__setitem__("thickness", "abc"),
        lambda d: d["wall"].pop("thickness"),
        lambda d: d["wall"].pop("masonry"),
        lambda d: d["wall"].__setitem__("thicknes", 1),
        lambda d: d["interventions"][1].__setitem__("ratio", 25),
        lambda d: d["interventions"][0].__setitem__("material", "gfrp"),
        lambda d: d["seismic"]["records"]["artificial"].__setitem__("count", 7.5),
        lambda d: d["seismic"].__setitem__("spectrum", {"type": "ntc", "ag": 0.2}),
    ],
)
def test_first_problem_is_the_loaders_error(change):
    data = small_data()
    change(data)
    exc = _loader_error(copy.deepcopy(data))
    project, problems = validate_edit(data)
    assert project is None and problems, "the editor must see the problem too"
    assert problems[0].message == exc.message
    assert (problems[0].key or None) == exc.key


def test_missing_key_points_at_its_field():
    data = small_data()
    data["wall"].pop("thickness")
    _, (p,) = validate_edit(data)
    assert p.path == ("wall",)
    assert p.target == ("wall", "thickness")
    assert p.message.startswith("missing required key 'thickness'")


def test_valid_data_has_no_problem_and_round_trips():
    data = small_data()
    project, problems = validate_edit(data)
    assert problems == [] and project == validate_data(data)
    assert validate_data(project_data(project)) == project


def test_missing_record_file_uses_the_loaders_message(tmp_path):
    data = small_data()
    data["seismic"]["records"] = {"files": [{"path": "nope.AT2"}]}
    project = validate_data(data)
    p = record_file_problem(project, tmp_path)
    assert p is not None
    assert p.target == ("seismic", "records", "files", 0, "path")
    assert p.message.startswith("record file 'nope.AT2' not found")


def test_derived_wall_values_are_the_dynamics_ones():
    d = wall_derived(
        {"thickness": 0.4, "height": 3.0, "masonry": "rubble-stone", "mechanism": "two-sided"}
    )
    w = Wall(0.4, 3.0, 19e3)
    assert not isinstance(d, str)
    assert d.alpha == pytest.approx(w.alpha)
    assert d.R == pytest.approx(w.R)
    assert d.p == pytest.approx(w.p)
    # pivot: crushing (the default): rubble stone LC1, f_d = 1.0/1.35 MPa, W = 22.8 kN/m,
    # x_W = 22.8/(0.85·740.7) = 0.036212 m, a_RM = (B − x_W)/H (tests/assess/test_wall_model.py)
    assert d.a_rm == pytest.approx((0.4 - 0.036212) / 3.0, abs=1e-6)
    edge = wall_derived(
        {"thickness": 0.4, "height": 3.0, "masonry": "rubble-stone", "mechanism": "two-sided"},
        {"pivot": "edge"},
    )
    assert not isinstance(edge, str) and edge.a_rm == pytest.approx(0.4 / 3.0)
    assert d.alpha_deg == pytest.approx(math.degrees(w.alpha))
    bad = wall_derived({"thickness": 4, "height": 3.0, "unit_weight": 18, "mechanism": "one-sided"})
    assert isinstance(bad, str) and "thickness" in bad


def test_spectrum_preview():
    s = spectrum_preview({"type": "preset", "name": "A2"})
    assert s.pga_g == pytest.approx(0.106)
    assert isinstance(spectrum_preview({"type": "preset", "name": "A9"}), str)
    ntc = spectrum_preview(
        {"type": "ntc2018", "ag": 0.261, "F0": 2.36, "Tc_star": 0.347, "soil": "B"}
    )
    assert ntc.sa([0.0])[0] == pytest.approx(ntc.pga_g)


def test_frp_mass_per_metre():
    wall = wall_derived(
        {"thickness": 0.3, "height": 3.0, "unit_weight": 18, "mechanism": "one-sided"}
    )
    table = material_table({"GFRP": {"density": 2100.0}, "NEW": {"price": 3.0}})
    assert table["GFRP"].density == 2100.0
    assert "NEW" not in table  # incomplete: skipped while it is typed
    wall_data = {"thickness": 0.3, "height": 3.0}
    ext = frp_mass_per_m(wall, wall_data, table["GFRP"], "external", 1.0)
    cen = frp_mass_per_m(wall, wall_data, table["GFRP"], "centred", 1.0)
    assert ext == pytest.approx(1e-3 * 0.3 * 2 * 3.0 * 2100.0)
    assert cen == pytest.approx(ext / 2)
    assert frp_mass_per_m(wall, wall_data, table["GFRP"], "external", "abc") is None


def test_render_plot_fits_and_draws():
    lines = render_plot(
        [Series([0, 1, 2], [0, 1, 0], label="tri"), Series([1], [0.5], kind="points")],
        40,
        10,
        rules=[Rule(0.5, "y", label="half")],
        x_label="x",
        y_label="y",
    )
    assert len(lines) == 10
    assert all(isinstance(t, Text) and t.cell_len <= 40 for t in lines)
    body = "".join(t.plain for t in lines)
    assert any(0x2800 < ord(ch) <= BRAILLE_BASE + 0xFF for ch in body)
    assert "●" in body and "tri" in lines[0].plain
    assert render_plot([Series([0], [0])], 5, 3)  # tiny sizes do not fail
    assert data_range([None, float("nan")]) == (0.0, 1.0)
    assert tick(0.000123) == "1.2e-4" and tick(12.5) == "12.5"


def test_case_progress_counts_every_pair_once(tmp_path):
    """Per-case bars from the API's case_progress callback: each (case, record) IDA is counted
    once, whether computed (first run) or taken from the cache (rerun)."""
    project = load_project_text(SMALL, "small.yaml").project
    inputs = inputs_from_project(project, tmp_path)
    seismic = prepare_records(inputs)
    for expected_computed in (9, 0):
        tracker = CaseProgress(inputs, len(seismic.records))
        assert tracker.names == ["Unreinforced", "GFRP external 1‰", "CFRP centred 2‰"]
        assert [c.done for c in tracker.counts()] == [0, 0, 0]
        _, stats = run_assessment(
            inputs, tmp_path, seismic=seismic, pdf=False, jobs=2, case_progress=tracker.mark
        )
        assert stats.computed == expected_computed
        assert [(c.done, c.total) for c in tracker.counts()] == [(3, 3)] * 3


@pytest.mark.slow
def test_load_previous_rebuilds_the_last_run_only_when_it_matches(tmp_path):
    """Opening a project shows its last run again, rebuilt from the cache without writing; a
    project changed since (an IDA not in the cache) or never run gives None."""
    import threading

    from frp_assess.tui.core.session import load_previous

    project = load_project_text(SMALL, "small.yaml").project
    stop = threading.Event()
    assert load_previous(project, tmp_path, "small.yaml", tmp_path, cancel=stop) is None
    inputs = inputs_from_project(project, tmp_path, "small.yaml")
    stored, _ = run_assessment(inputs, tmp_path, pdf=False, jobs=2, created="2026-01-02")
    before = {p.name: p.stat().st_mtime_ns for p in tmp_path.iterdir()}
    got = load_previous(project, tmp_path, "small.yaml", tmp_path, cancel=stop)
    assert got is not None and got.stats.computed == 0
    assert got.results == stored  # the same numbers, and the stored run's date
    assert {p.name: p.stat().st_mtime_ns for p in tmp_path.iterdir()} == before  # nothing written
    changed = load_project_text(
        SMALL.replace("seed: 7", "seed: 8"), "small.yaml"
    ).project  # other records: no cached IDA
    assert load_previous(changed, tmp_path, "small.yaml", tmp_path, cancel=stop) is None


@pytest.mark.slow
def test_load_previous_reads_the_stored_run_when_the_file_is_unchanged(tmp_path):
    """Opening a project file whose last run is that of the file as it is (the rule of an
    unchanged ``run``) shows that run as stored: nothing is recomputed, so it is shown even
    with the IDA cache gone (rebuilding would need it).  A results.json replaced since, or
    a changed file, is not believed: the run is rebuilt from the cache, here gone, so
    nothing is shown."""
    import shutil
    import threading

    from frp_assess.app.assessment import prepare_run, run_prepared
    from frp_assess.tui.core.session import load_previous

    path = tmp_path / "small.yaml"
    path.write_text(SMALL, encoding="utf-8")
    project = load_project_text(SMALL, "small.yaml").project
    out = tmp_path / "small-results"
    stop = threading.Event()
    stored = run_prepared(
        prepare_run(project, tmp_path, "small.yaml"), out, cancel=stop, jobs=2, project_file=path
    ).results
    assert stored.inputs_digest
    shutil.rmtree(out / ".cache")
    args = (project, tmp_path, "small.yaml", out)
    assert load_previous(*args, cancel=stop) is None  # rebuilding needs the cache
    got = load_previous(*args, cancel=stop, project_file=path)
    assert got is not None and got.results == stored and got.stats.computed == 0
    results = out / "results.json"
    text = results.read_text(encoding="utf-8")
    results.write_text(text.replace('"created"', ' "created"', 1), encoding="utf-8")
    assert load_previous(*args, cancel=stop, project_file=path) is None  # not the run's file
    results.write_text(text, encoding="utf-8")
    assert load_previous(*args, cancel=stop, project_file=path) is not None
    path.write_text(SMALL + "\n# edited\n", encoding="utf-8")
    assert load_previous(*args, cancel=stop, project_file=path) is None


def test_save_project_refuses_bad_paths_and_says_whether_comments_were_kept(tmp_path):
    """A bad file name is refused with the same message the save dialog shows; a new file
    gets the whole project, an opened one keeps its text (here, its comment)."""
    from frp_assess.config import load_project
    from frp_assess.tui.core.session import save_project, yaml_path_problem

    project = load_project_text(SMALL, "small.yaml").project
    for bad in (tmp_path / "wall.txt", tmp_path / "no-such-dir" / "wall.yaml", tmp_path):
        with pytest.raises(InputError) as info:
            save_project(project, bad)
        assert info.value.message == yaml_path_problem(bad)
    fresh = tmp_path / "fresh.yaml"
    assert save_project(project, fresh) is False
    assert load_project(fresh).project == project
    opened = tmp_path / "opened.yaml"
    opened.write_text("# site survey of May\n" + SMALL, encoding="utf-8")
    changed = validate_data({**project_data(project), "costs": {"currency": "CHF"}})
    assert save_project(changed, opened, opened_from=opened) is True
    assert opened.read_text(encoding="utf-8").startswith("# site survey of May\n")
    assert load_project(opened).project == changed
