"""The application API end to end on a small project: files, consistency, cache, cancel."""

from __future__ import annotations

import json
import threading

import pytest

from frp_assess.api import run_assessment
from frp_assess.assess.inputs import (
    ArtificialRecords,
    AssessmentInputs,
    CostSettings,
    DesignRequest,
    Material,
    RetrofitOption,
)
from frp_assess.dynamics import ida
from frp_assess.errors import Cancelled
from frp_assess.motions import preset_spectrum
from frp_assess.results.json_io import from_json, to_json

GFRP = Material("GFRP", 46.0, 0.015, 2000.0, 8.0, "test")
CFRP = Material("CFRP", 150.0, 0.013, 1550.0, 35.0, "test")


def small_inputs(**kw) -> AssessmentInputs:
    base = dict(
        thickness=0.3,
        height=3.0,
        unit_weight=18.0,
        mechanism="one-sided",
        length=5.0,
        spectrum=preset_spectrum("A2"),
        records=ArtificialRecords(count=3, seed=7, duration=14.0, dt=0.01),
        options=(
            RetrofitOption("GFRP ext 1", GFRP, "external", 1.0),
            RetrofitOption("CFRP cen 2", CFRP, "centred", 2.0),
        ),
        costs=CostSettings("EUR", 100.0),
        target=3.0,
        project={"name": "Test <&> wall"},
    )
    base.update(kw)
    return AssessmentInputs(**base)


def test_run_writes_consistent_results(tmp_path):
    inputs = small_inputs(design=DesignRequest((GFRP,), ("external",), (0.5, 3.0), 0.25))
    results, stats = run_assessment(inputs, tmp_path, jobs=2, pdf=False, created="2026-01-01")
    assert stats.computed > 0
    assert {p.name for p in tmp_path.iterdir()} >= {
        "results.json",
        "results.csv",
        "spectra.csv",
        "records",
    }
    on_disk = json.loads((tmp_path / "results.json").read_text())
    assert on_disk == json.loads(to_json(results))
    assert from_json((tmp_path / "results.json").read_text()) == results  # round trip
    cases = results.cases
    assert cases[0].name == "Unreinforced" and cases[0].rank is None
    demand = results.demand.pga
    assert demand == pytest.approx(0.106)
    # every number traceable: recompute one IDA directly
    rec = results.records[1]
    from frp_assess.motions import read_record

    acc = read_record(tmp_path / "records" / f"{rec.name}.AT2")
    direct = ida(inputs.model_for(inputs.options[0]), acc.acc, acc.dt, inputs.ida)
    assert cases[1].records[1].collapse_multiplier == pytest.approx(
        direct.collapse_multiplier, rel=1e-5
    )
    for c in cases:
        a = [r.a_dyn for r in c.records]
        assert c.min_a_dyn == pytest.approx(min(a))
        # FC = 1.35, LC1's (Circolare 2019 Tab. C8.5.IV), divides the IDA capacity by default
        assert c.fc == 1.35
        assert c.capacity_demand == pytest.approx(c.design_a_dyn / (1.35 * demand))
        assert c.improvement == pytest.approx(c.design_a_dyn / cases[0].design_a_dyn)
        # meets_target is the IDA check alone (false for a dropped option); the verdict,
        # passes, needs every deciding check (the IDA's among them)
        dropped = c.pivot is not None and c.pivot.dropped and c.rank is None and c.ratio > 0
        assert c.meets_target == (c.capacity_demand >= 3.0 and not dropped)
        assert c.passes is not None and (not c.passes or c.meets_target)
        assert c.governing_check in {x.name for x in c.deciding_checks}
        assert c.recommended == (c.name == results.recommended)
    # fewer than 7 records: the design value is the least favourable record
    assert cases[1].design_a_dyn == pytest.approx(cases[1].min_a_dyn)
    # options failing the pivot check get no rank; the others rank 1, 2, ...
    kept = [c for c in cases[1:] if not c.pivot.dropped]
    assert sorted(c.rank for c in kept) == list(range(1, len(kept) + 1))
    assert all(c.rank is None for c in cases[1:] if c.pivot.dropped)
    d = results.design[0]
    assert d.ratio is None or d.capacity_demand >= 3.0
    # a design answer is a case of the results, decided like the others: it passes
    if d.ratio is not None:
        answer = results.case(d.case)
        assert answer is not None and answer.passes
    # the answer's bars as built: they install at least the ratio found, and its FRP mass and
    # cost are theirs
    if d.ratio is None:
        assert d.as_built is None
    else:
        assert d.as_built is not None and d.as_built.ratio_installed >= d.ratio
        assert (d.frp_mass, d.frp_cost) == (d.as_built.mass, d.as_built.cost)
    lines = (tmp_path / "results.csv").read_text().splitlines()
    assert len(lines) == 1 + len(cases) * 3
    assert results.governing.runs[0].collapsed is True
    assert results.governing.runs[1].collapsed is False


@pytest.mark.slow
def test_rerun_is_served_from_cache_with_same_numbers(tmp_path):
    inputs = small_inputs()
    first, s1 = run_assessment(inputs, tmp_path, pdf=False, created="x")
    second, s2 = run_assessment(inputs, tmp_path, pdf=False, created="x")
    assert s2.computed == 0 and s2.reused == s1.computed
    assert first == second
    changed, s3 = run_assessment(small_inputs(target=1.5), tmp_path, pdf=False, created="x")
    assert s3.computed == 0  # the target does not change any IDA
    other, s4 = run_assessment(small_inputs(strain_factor=0.4), tmp_path, pdf=False, created="x")
    assert s4.computed == 2 * 3  # only the reinforced cases depend on the strain factor


class PairRecorder:
    """Collects case_progress calls and checks none lags behind the overall "ida" count."""

    def __init__(self) -> None:
        self.lock = threading.Lock()
        self.pairs: list[tuple[int, int]] = []
        self.lagging: list[tuple[int, int]] = []

    def mark(self, case: int, record: int) -> None:
        with self.lock:
            self.pairs.append((case, record))

    def progress(self, stage: str, done: int, total: int) -> None:
        if stage == "ida":
            with self.lock:
                if len(self.pairs) < done:
                    self.lagging.append((len(self.pairs), done))


@pytest.mark.slow
def test_case_progress_names_every_case_record_pair_once(tmp_path):
    """case_progress gets each (case, record) of the IDA stage exactly once, before the
    overall count that includes it: on a fresh run, on a partly cached run (after a change
    that only affects the reinforced cases) and on a fully cached one."""
    for inputs, computed in (
        (small_inputs(), 9),
        (small_inputs(strain_factor=0.4), 6),
        (small_inputs(strain_factor=0.4), 0),
    ):
        rec = PairRecorder()
        _, stats = run_assessment(
            inputs, tmp_path, jobs=2, pdf=False, progress=rec.progress, case_progress=rec.mark
        )
        assert stats.computed == computed
        assert sorted(rec.pairs) == [(c, r) for c in range(3) for r in range(3)]
        assert not rec.lagging


def test_cancel_keeps_finished_results(tmp_path):
    inputs = small_inputs()
    stop = threading.Event()
    seen = []

    def progress(stage, done, total):
        if stage == "ida" and done >= 2:
            seen.append(done)
            stop.set()

    with pytest.raises(Cancelled):
        run_assessment(inputs, tmp_path, jobs=1, progress=progress, cancel=stop, pdf=False)
    assert not (tmp_path / "results.json").exists()  # nothing half-written
    cached = len(list((tmp_path / ".cache").glob("*.json")))
    assert cached >= 2
    _, stats = run_assessment(inputs, tmp_path, jobs=1, pdf=False)
    assert stats.reused == cached and stats.computed == 9 - cached
