"""The application functions the CLI and the TUI call (api.py, after run_assessment).

References are independent of the code under test: IDAs computed directly with
:func:`frp_assess.dynamics.ida`, and the mean of docs/model.md §5 written out by hand (a
record without collapse up to C_max counts at C_max·C₀·PGA).
"""

from __future__ import annotations

import threading
from pathlib import Path

import pytest

from frp_assess import api
from frp_assess.dynamics import IdaSettings, RockingModel, ida
from frp_assess.dynamics.units import rebars_from_practice, wall_from_practice
from frp_assess.motions import Record
from tests.conftest import G, synthetic_record

WALL = wall_from_practice(0.25, 3.0, 18.0)
MODEL = RockingModel(WALL, "one-sided", rebars_from_practice(40.0, 0.02, "external", 1.0))
#: small settings: few runs, one record that does not collapse below C_max = 2·C0
SETTINGS = IdaSettings(step_ratio=1.5, tolerance=0.05, max_multiplier=2.0)


@pytest.fixture(scope="module")
def records() -> list[Record]:
    return [
        Record(f"syn-{i}", 0.01, synthetic_record(seed=20 + i, duration=4.0, pga_g=pga))
        for i, pga in enumerate((0.3, 0.5, 0.02))
    ]


def test_run_ida_is_the_direct_ida_with_the_mean_of_run(records, tmp_path: Path) -> None:
    direct = [ida(MODEL, r.acc, r.dt, SETTINGS) for r in records]
    assert any(d.a_dyn is None for d in direct), "the test needs a record without collapse"
    out = api.run_ida(MODEL, records, SETTINGS, jobs=1, cache_dir=tmp_path)
    assert out.results == tuple(direct) and out.computed == len(records)
    bounded = [
        d.a_dyn / G if d.a_dyn is not None else SETTINGS.max_multiplier * d.c0 * d.pga / G
        for d in direct
    ]
    assert out.summary.mean_a_dyn == pytest.approx(sum(bounded) / len(bounded), rel=1e-12)
    assert out.summary.min_a_dyn == pytest.approx(min(bounded), rel=1e-12)
    assert out.summary.lower_bound
    assert out.design_value.startswith("least favourable")  # 3 records, fewer than 7
    again = api.run_ida(MODEL, records, SETTINGS, jobs=1, cache_dir=tmp_path)
    assert again.computed == 0 and again.results == out.results


def test_simulate_is_one_time_history(records) -> None:
    rec = records[0]
    res = api.simulate(MODEL, rec, 1.3, history=True)
    ref = MODEL.run(rec.acc, rec.dt, 1.3, history=True)
    assert res.max_rotation == ref.max_rotation and res.history is not None
    with pytest.raises(ValueError, match="multiplier must be > 0"):
        api.simulate(MODEL, rec, 0.0)


def test_new_project_text_names_the_project_after_the_file() -> None:
    text = api.new_project_text(Path("north_wall.yaml"), "project:\n  name: Example wall\n")
    assert text == "project:\n  name: north wall\n"
    quoted = api.new_project_text(Path("a: b.yaml"), "name: Example wall\n")
    assert quoted == 'name: "a: b"\n'
    assert api.new_project_text(None, "name: Example wall\n") == "name: Example wall\n"


def test_run_study_without_figures(tmp_path: Path) -> None:
    from frp_assess.study import parse_study
    from tests.study.conftest import TINY, tiny_records

    stats, written = api.run_study(
        parse_study(dict(TINY)),
        tmp_path,
        jobs=1,
        records=tiny_records(),
        figures=False,
        cancel=threading.Event(),
    )
    assert written == [] and stats.computed == 6 * 3
    assert (tmp_path / "summary.csv").is_file() and not (tmp_path / "study.pdf").exists()
