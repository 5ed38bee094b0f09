"""The project's ``wall.loads`` through the assessment's inputs (docs/model.md §12): the
practitioners' units, the SI of the model (k_t, F_y, F_a/i_t by hand from
rules/tie_rods.py's formulas), every case's model, the cache key and results.json's record."""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import pytest

from frp_assess.assess.cache import task_key
from frp_assess.assess.from_project import load_inputs
from frp_assess.assess.load_inputs import LoadsInput, TieInput
from frp_assess.assess.loads_record import loads_result
from frp_assess.dynamics import IdaSettings
from frp_assess.dynamics.loads import NO_LOADS
from frp_assess.results.carried_loads import LoadsResult
from frp_assess.results.json_io import from_data, to_data

FIXTURE = Path(__file__).parents[1] / "fixtures" / "facade-loads.yaml"
#: a bundled project without loads (the paper's case)
NO_LOADS_PROJECT = Path(__file__).parents[2] / "projects" / "paper-case.yaml"


def test_project_loads_reach_every_model_in_si() -> None:
    """The fixture's floor 10 kN/m at 0.3 m (carried), roof 4 kN/m at 0.2 m (restrained),
    thrust 1 kN/m at 5.5 m, tie Ø20 every 3 m, 8 m long, S235, E 210 GPa:
    k_t = 210e9·(π·0.020²/4)/(8·3) = 2.748894e6 N/m per m, F_y = 235e6·π·0.020²/4/3 N/m."""
    inputs = load_inputs(FIXTURE, warn=None)
    assert [p.name for p in inputs.loads.top] == ["first floor", "roof"]
    assert [p.carried for p in inputs.loads.top] == [True, False]
    area = math.pi * 0.020**2 / 4.0
    for model in inputs.case_models():
        loads = model.loads
        assert [(p.force, p.distance) for p in loads.top] == [(10e3, 0.3), (4e3, 0.2)]
        assert [(f.force, f.height) for f in loads.thrusts] == [(1e3, 5.5)]
        (tie,) = loads.ties
        assert tie.height == 5.8
        assert tie.stiffness == pytest.approx(210e9 * area / (8.0 * 3.0), rel=1e-12)
        assert tie.yield_force == pytest.approx(235e6 * area / 3.0, rel=1e-12)
        assert tie.anchorage_force == math.inf


def test_anchorage_per_metre_and_no_loads_is_the_default_model() -> None:
    """F_a = 30 kN per tie every 3 m: 10 kN/m.  A project without loads builds models with
    the very NO_LOADS of the model's default."""
    tie = TieInput("t", 3.0, 314.0, 3.0, 6.0, anchorage=30.0).tie()
    assert tie.anchorage_force == pytest.approx(10e3, rel=1e-12)
    inputs = load_inputs(NO_LOADS_PROJECT, warn=None)
    assert not inputs.loads
    assert all(m.loads is NO_LOADS for m in inputs.case_models())


def test_cache_key_has_the_loads_only_when_there_are_loads() -> None:
    """The key changes with the loads (another load, another key) and a model without
    loads keeps the key it had (the payload gains no ``loads`` entry)."""
    inputs = load_inputs(FIXTURE, warn=None)
    loaded = inputs.model_for(None)
    bare = replace(loaded, loads=NO_LOADS)
    record, ida = "0" * 64, IdaSettings()
    other = replace(inputs, loads=replace(inputs.loads, thrusts=())).model_for(None)
    keys = {task_key(m, record, ida) for m in (loaded, bare, other)}
    assert len(keys) == 3
    empty = replace(inputs, loads=LoadsInput()).model_for(None)
    assert task_key(empty, record, ida) == task_key(bare, record, ida)


def test_results_record_of_the_loads_round_trips() -> None:
    """results.json's ``loads``: each load as given, the tie's per-metre values in kN/m, and
    α₀ term by term; read back as the same object.  None without loads."""
    inputs = load_inputs(FIXTURE, warn=None)
    record = loads_result(inputs)
    assert record is not None
    (tie,) = record.ties
    assert tie.stiffness == pytest.approx(210e6 * math.pi * 0.020**2 / 4.0 / 24.0, rel=1e-12)
    assert tie.capacity == tie.yield_force and tie.ductile and tie.anchorage_force is None
    data = json.loads(json.dumps(to_data(record)))
    assert from_data(LoadsResult, data) == record
    assert loads_result(load_inputs(NO_LOADS_PROJECT, warn=None)) is None


def test_validate_summary_names_every_load(capsys: pytest.CaptureFixture[str]) -> None:
    """`validate` prints one line with every load, its lever and whether its mass is carried;
    the tie's F_y = 314.16 mm²·235 MPa/3 m = 24.6 kN/m, ductile (no anchorage given)."""
    from frp_assess.cli import main

    assert main(["validate", str(FIXTURE)]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[2] == (
        "  loads: first floor 10 kN/m at d = 0.3 m (carried); roof 4 kN/m at d = 0.2 m "
        "(restrained); rafters 1 kN/m outward at h = 5.5 m; catena A_s = 314.2 mm2 every 3 m "
        "at h_t = 5.8 m (F_y = 24.6 kN/m, ductile)"
    )
    assert out[3].startswith("  spectrum:")


def _schema_text() -> str:
    """What `frp-assess schema` prints."""
    import contextlib
    import io

    from frp_assess.cli import main

    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        assert main(["schema"]) == 0
    return buffer.getvalue()


def test_the_template_documents_wall_loads(tmp_path: Path) -> None:
    """templates/wall.yaml's commented `wall.loads` example, uncommented, is a valid project
    with a floor, a thrust and a tie (and the JSON Schema of `frp-assess schema` has the block,
    from the pydantic model)."""
    import frp_assess

    template = Path(frp_assess.__file__).parent / "templates" / "wall.yaml"
    lines = template.read_text(encoding="utf-8").splitlines()
    start = lines.index(
        "  # loads:                     # optional: what bears on and pushes the wall, per metre of"
    )
    out = list(lines)
    i = start
    while lines[i].startswith("  #"):
        out[i] = "  " + lines[i][4:]
        i += 1
    path = tmp_path / "p.yaml"
    path.write_text("\n".join(out) + "\n", encoding="utf-8")
    inputs = load_inputs(path, warn=None)
    assert [p.name for p in inputs.loads.top] == ["first floor"]
    assert [t.anchorage for t in inputs.loads.ties] == [40.0]
    assert len(inputs.loads.thrusts) == 1
    capsys_text = _schema_text()
    text = json.dumps(json.loads(capsys_text))
    for key in ("TopLoadSpec", "ThrustSpec", "TieSpec", "WallLoadsSpec"):
        assert key in text, key
