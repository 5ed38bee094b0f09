"""A wall above the ground floor: the IDA runs on the floor motion, a_dyn stays in ground terms.

References are independent of the runner: the floor motion is
:func:`frp_assess.motions.floor.floor_acceleration` (tested on its own in
tests/motions/test_floor.py) fed straight to :class:`RockingModel`; PGAs are max|acc| taken
here with numpy; a_RM = g·B/H is written out by hand (docs/model.md §1).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from frp_assess.assess.cache import IdaCache, record_digest, task_key
from frp_assess.assess.floor_input import (
    floor_record,
    floor_spectra,
    in_ground_terms,
)
from frp_assess.assess.inputs import (
    ArtificialRecords,
    AssessmentInputs,
    BuildingSettings,
    Material,
    RetrofitOption,
)
from frp_assess.assess.runner import IdaRunner
from frp_assess.dynamics import IdaSettings, ModelOptions
from frp_assess.motions import G, Record, preset_spectrum, response_spectrum
from frp_assess.motions.floor import floor_acceleration

GFRP = Material("GFRP", 46.0, 0.015, 2000.0, 8.0, "test")
SETTINGS = IdaSettings(step_ratio=1.2, tolerance=0.01, max_multiplier=50.0)
#: a gable on the top floor of a 3-storey building, T1 between the record's two frequencies
TOP = BuildingSettings(height=10.0, storeys=3, wall_base=9.0, period=0.3, damping=0.05)


def burst(name: str, seed: int, duration: float = 8.0, dt: float = 0.01) -> Record:
    """A deterministic ground motion [m/s²]: three sines under a sine envelope."""
    rng = np.random.default_rng(seed)
    t = np.arange(0.0, duration, dt)
    freqs = (1.5, 3.3, 6.0)
    phases = rng.uniform(0.0, 2.0 * math.pi, 3)
    acc = sum(np.sin(2.0 * math.pi * f * t + p) for f, p in zip(freqs, phases, strict=True))
    return Record(name, dt, 1.5 * np.sin(math.pi * t / duration) * acc, f"burst seed {seed}")


RECORDS = [burst("b1", 1), burst("b2", 2)]


def inputs(building: BuildingSettings | None, **kw: object) -> AssessmentInputs:
    base: dict[str, object] = dict(
        thickness=0.3,
        height=3.0,
        unit_weight=18.0,
        mechanism="one-sided",
        spectrum=preset_spectrum("A2"),
        records=ArtificialRecords(count=2, seed=1, duration=14.0, dt=0.01),
        options=(RetrofitOption("GFRP ext 1", GFRP, "external", 1.0),),
        ida=SETTINGS,
        building=building,
        model=ModelOptions(pivot="edge"),  # the hand values below: a_RM = g·B/H
    )
    base.update(kw)
    return AssessmentInputs(**base)  # type: ignore[arg-type]


def test_wall_at_ground_level_of_a_building_gives_the_ground_results() -> None:
    """Z = 0: ψ1 = 0, the floor motion is the ground record, every number is the same."""
    at_ground = inputs(BuildingSettings(10.0, 3, 0.0, 0.3))
    without = inputs(None)
    models = without.case_models()
    a = IdaRunner(RECORDS, at_ground, IdaCache(None), jobs=1).run(models)
    b = IdaRunner(RECORDS, without, IdaCache(None), jobs=1).run(models)
    assert a == b


def test_top_floor_ida_runs_on_the_floor_motion_and_reports_ground_terms() -> None:
    inp = inputs(TOP)
    model = inp.model_for(None)
    [results] = IdaRunner(RECORDS, inp, IdaCache(None), jobs=1).run([model])
    a_rm = G * 0.3 / 3.0  # g·tan α, tan α = B/H
    for rec, res in zip(RECORDS, results, strict=True):
        floor = floor_acceleration(
            rec.acc, rec.dt, height_building=10.0, storeys=3, wall_base=9.0, period=0.3
        )
        pga_ground = float(np.max(np.abs(rec.acc)))
        pga_floor = float(np.max(np.abs(floor)))
        assert pga_floor > 1.2 * pga_ground  # the floor amplifies: the test can tell them apart
        assert res.pga == pytest.approx(pga_ground, rel=1e-12)
        assert res.c0 == pytest.approx(a_rm / pga_floor, rel=1e-12)  # nothing moves below
        c = res.collapse_multiplier
        assert c is not None and res.a_dyn is not None and res.q is not None
        assert res.a_dyn == pytest.approx(c * pga_ground, rel=1e-12)
        assert res.q == pytest.approx(c * pga_ground / a_rm, rel=1e-12)
        # the multipliers are of the wall shaken by C·(floor motion): the first collapse on
        # the sampling falls there, the survivor stands
        assert res.first_collapse is not None
        assert model.run(floor, rec.dt, res.first_collapse).collapsed
        assert res.survivor_multiplier is not None
        assert not model.run(floor, rec.dt, res.survivor_multiplier).collapsed
        assert res.survivor_multiplier <= c  # the largest standing sample below the capacity


def test_in_ground_terms_keeps_the_multipliers() -> None:
    from frp_assess.dynamics import ida

    inp = inputs(TOP)
    model = inp.model_for(None)
    rec = RECORDS[0]
    floor = floor_record(rec, TOP)
    direct = ida(model, floor.acc, floor.dt, SETTINGS)
    ground = in_ground_terms(direct, rec.pga)
    assert ground.collapse_multiplier == direct.collapse_multiplier
    assert ground.c0 == direct.c0 and ground.curve == direct.curve
    assert direct.a_dyn == pytest.approx(direct.collapse_multiplier * floor.pga)  # floor terms
    assert ground.a_dyn == pytest.approx(direct.collapse_multiplier * rec.pga)


def test_cache_key_changes_with_the_building(tmp_path: Path) -> None:
    model = inputs(None).model_for(None)
    h = record_digest(RECORDS[0].acc, RECORDS[0].dt)
    ground = task_key(model, h, SETTINGS)
    assert task_key(model, h, SETTINGS, None) == ground  # ground walls keep their old keys
    keys = {
        ground,
        task_key(model, h, SETTINGS, TOP),
        task_key(model, h, SETTINGS, BuildingSettings(10.0, 3, 8.0, 0.3)),
        task_key(model, h, SETTINGS, BuildingSettings(10.0, 3, 9.0, 0.35)),
        task_key(model, h, SETTINGS, BuildingSettings(10.0, 4, 9.0, 0.3)),
        task_key(model, h, SETTINGS, BuildingSettings(10.0, 3, 9.0, 0.3, 0.08)),
        task_key(model, h, SETTINGS, BuildingSettings(12.0, 3, 9.0, 0.3)),
    }
    assert len(keys) == 7
    # a run with another building computes again; the same building reuses
    cache = IdaCache(tmp_path)
    models = [model]
    first = IdaRunner(RECORDS[:1], inputs(TOP), cache, jobs=1)
    first.run(models)
    again = IdaRunner(RECORDS[:1], inputs(TOP), cache, jobs=1)
    assert again.run(models) == first.run(models)
    assert again.reused == 1 and again.computed == 0
    moved = IdaRunner(RECORDS[:1], inputs(BuildingSettings(10.0, 3, 5.0, 0.3)), cache, jobs=1)
    moved.run(models)
    assert moved.computed == 1


def test_floor_record_is_the_record_at_ground_level() -> None:
    rec = RECORDS[0]
    assert floor_record(rec, None) is rec
    floor = floor_record(rec, TOP)
    assert floor.name == rec.name and floor.dt == rec.dt and floor.npts == rec.npts
    assert "Z = 9 m" in floor.source


def test_floor_spectra_of_a_run() -> None:
    """The records' floor spectra are response spectra of the floor motions; T1 and the
    plateau ends are on the grid; the code curve's plateau is 1.1/√ξ1·a_Z,1 with
    a_Z,1 = Se(T1)·γ1·Z/H·√(1 + 0.0004·5²) (Circolare eqs. C7.2.6-C7.2.10, by hand)."""
    spectrum = preset_spectrum("A2")
    out = floor_spectra(RECORDS, spectrum, TOP)
    T = np.asarray(out.periods)
    assert {0.24, 0.3, 0.33} <= {round(t, 12) for t in out.periods}
    floor = floor_acceleration(
        RECORDS[1].acc, 0.01, height_building=10.0, storeys=3, wall_base=9.0, period=0.3
    )
    assert out.records[1] == pytest.approx(response_spectrum(floor, 0.01, T) / G, rel=1e-9)
    assert out.mean == pytest.approx(np.mean(out.records, axis=0), rel=1e-12)
    assert out.floor_pga[1] == pytest.approx(np.max(np.abs(floor)) / G, rel=1e-12)
    assert out.ground_pga[0] == pytest.approx(np.max(np.abs(RECORDS[0].acc)) / G, rel=1e-12)
    se_t1 = out.ground[out.periods.index(0.3)]
    gamma = 3 * 3 / (2 * 3 + 1)
    plateau = 1.1 / math.sqrt(0.05) * se_t1 * gamma * 0.9 * math.sqrt(1 + 0.0004 * 25)
    assert out.code[out.periods.index(0.3)] == pytest.approx(plateau, rel=1e-9)
    assert out.code[out.periods.index(0.24)] == pytest.approx(plateau, rel=1e-9)
    # the run passes the floor motions its IDA ran on: the same spectra, nothing filtered twice
    runner = IdaRunner(RECORDS, inputs(TOP), IdaCache(None), jobs=1)
    assert floor_spectra(RECORDS, spectrum, TOP, floors=runner.motions) == out


def test_governing_histories_and_missing_idas_use_the_floor_motion(tmp_path: Path) -> None:
    """The report's time histories run on the floor motion at the collapse multiplier
    (the wall falls) and just below it (it stands); the count of IDAs missing from the
    cache is taken with the building's keys."""
    from types import SimpleNamespace

    from frp_assess.api import CACHE_DIR, governing_histories, missing_idas

    inp = inputs(TOP)
    runner = IdaRunner(RECORDS, inp, IdaCache(tmp_path / CACHE_DIR), jobs=1)
    results = runner.run(inp.case_models())
    cases = [SimpleNamespace(name=n) for n in inp.case_names()]
    gov = governing_histories(inp, cases, RECORDS, results, None)  # type: ignore[arg-type]
    assert gov is not None and gov.case == "Unreinforced"
    k = min(range(len(RECORDS)), key=lambda i: results[0][i].collapse_multiplier or math.inf)
    assert gov.record == RECORDS[k].name
    collapse, below = gov.runs
    floor = floor_acceleration(
        RECORDS[k].acc, 0.01, height_building=10.0, storeys=3, wall_base=9.0, period=0.3
    )
    model = inp.model_for(None)
    for run in (collapse, below):
        direct = model.run(floor, 0.01, run.multiplier)
        assert run.collapsed == direct.collapsed
        assert run.peak_rotation_ratio == pytest.approx(direct.max_rotation_ratio, rel=1e-12)
    assert collapse.collapsed and not below.collapsed
    seismic = SimpleNamespace(records=RECORDS)
    assert missing_idas(inp, seismic, tmp_path) == 0  # type: ignore[arg-type]
    assert missing_idas(inputs(None), seismic, tmp_path) == 4  # type: ignore[arg-type]


def test_tui_time_history_runs_on_the_floor_motion() -> None:
    """The TUI's history viewer (tui/core/session.case_history) shakes the wall with the
    floor motion, as the IDA did: same peak θ/α as RockingModel on floor_acceleration."""
    from types import SimpleNamespace

    from frp_assess.tui.core.session import case_history

    inp = inputs(TOP)
    outcome = SimpleNamespace(
        inputs=inp,
        seismic=SimpleNamespace(records=RECORDS),
        results=SimpleNamespace(cases=[SimpleNamespace(name=n) for n in inp.case_names()]),
    )
    h = case_history(outcome, 1, 0, 0.3)  # type: ignore[arg-type]
    floor = floor_acceleration(
        RECORDS[0].acc, 0.01, height_building=10.0, storeys=3, wall_base=9.0, period=0.3
    )
    model = inp.model_for(inp.options[0])
    assert h.peak_ratio == pytest.approx(model.run(floor, 0.01, 0.3).max_rotation_ratio, 1e-12)
    assert h.peak_ratio != pytest.approx(model.run(RECORDS[0].acc, 0.01, 0.3).max_rotation_ratio)
