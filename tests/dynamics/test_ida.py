"""The IDA search rule of docs/model.md §5 (capacity: first-collapse) on stand-in models with a
known collapse set."""

from __future__ import annotations

import threading
from dataclasses import dataclass

import numpy as np
import pytest

from frp_assess.dynamics import IdaSettings, IdaTask, RockingModel, Wall, ida, run_batch
from frp_assess.errors import Cancelled
from tests.conftest import synthetic_record


@dataclass
class _Outcome:
    collapsed: bool
    max_rotation_ratio: float = 0.0

    @property
    def failure_mode(self) -> str | None:
        return "overturning" if self.collapsed else None


class StubModel:
    """Collapses for C in any of ``bands`` (list of (lo, hi)); counts calls."""

    def __init__(self, bands):
        self.wall = Wall(thickness=0.4, height=3.0, unit_weight=18e3)
        self.a_rm = self.wall.a_rm  # the edge pivot's
        self.crushing_rotation = np.inf  # the toe never crushes
        self.bands = bands
        self.calls = []

    def run(self, acc, dt, c):
        self.calls.append(c)
        return _Outcome(any(lo <= c <= hi for lo, hi in self.bands))


ACC = np.array([0.0, 1.0, -2.0, 0.5])  # PGA 2 m/s²


def test_bisection_brackets_the_threshold():
    c0 = Wall(thickness=0.4, height=3.0, unit_weight=18e3).a_rm / 2.0
    model = StubModel([(3.3 * c0, np.inf)])
    res = ida(model, ACC, 0.01, IdaSettings(capacity="first-collapse"))
    assert 3.3 * c0 <= res.collapse_multiplier <= 3.3 * c0 * 1.0051
    assert res.q == pytest.approx(res.collapse_multiplier / c0)
    assert res.a_dyn == pytest.approx(res.collapse_multiplier * 2.0)
    # the hunt tried C0·1.1^k up to the first collapse
    hunt = [c for c in model.calls if c <= 3.3 * c0]
    assert hunt[:3] == pytest.approx([c0, 1.1 * c0, 1.21 * c0])


def test_survivor_is_the_largest_multiplier_run_without_collapse():
    """docs/model.md §5: the bisection ends with C_lo (survives) and C_hi (first collapse),
    (C_hi - C_lo) <= tol·C_hi; C_lo is what "just below collapse" shows, so it must be a
    multiplier actually run and found standing, not C_hi·(1 - tol), which can fall."""
    c0 = Wall(thickness=0.4, height=3.0, unit_weight=18e3).a_rm / 2.0
    model = StubModel([(3.3 * c0, np.inf)])
    res = ida(model, ACC, 0.01, IdaSettings(capacity="first-collapse"))
    standing = [c for c in list(model.calls) if not any(lo <= c <= hi for lo, hi in model.bands)]
    assert res.survivor_multiplier == max(standing)
    assert res.collapse_multiplier - res.survivor_multiplier <= 0.005 * res.collapse_multiplier
    # collapse at the first try: nothing below was run
    assert ida(StubModel([(0.0, np.inf)]), ACC, 0.01).survivor_multiplier is None
    # no collapse up to C_max: the last (largest) multiplier of the hunt
    none = StubModel([])
    assert ida(none, ACC, 0.01, IdaSettings(max_multiplier=10.0)).survivor_multiplier == max(
        none.calls
    )


def test_curve_keeps_every_run_sorted():
    """The IDA curve holds every multiplier the search ran, in order, with its verdict."""
    c0 = Wall(0.4, 3.0, 18e3).a_rm / 2.0
    model = StubModel([(2.0 * c0, 2.2 * c0), (5.0 * c0, np.inf)])
    res = ida(model, ACC, 0.01)  # type: ignore[arg-type]
    assert [p.multiplier for p in res.curve] == sorted(model.calls)
    assert len(res.curve) == res.runs
    for p in res.curve:
        assert p.collapsed == any(lo <= p.multiplier <= hi for lo, hi in model.bands)


def test_first_collapse_not_a_later_one():
    """A wall that falls in a band and 'survives' above it: the first collapse counts."""
    c0 = Wall(thickness=0.4, height=3.0, unit_weight=18e3).a_rm / 2.0
    model = StubModel([(2.0 * c0, 2.2 * c0), (5.0 * c0, np.inf)])
    res = ida(model, ACC, 0.01, IdaSettings(capacity="first-collapse"))
    assert 2.0 * c0 <= res.collapse_multiplier <= 2.0 * c0 * 1.0051


def test_no_collapse_up_to_cmax():
    model = StubModel([])
    res = ida(model, ACC, 0.01, IdaSettings(max_multiplier=10.0))
    assert res.collapse_multiplier is None and res.q is None and res.a_dyn is None
    assert max(model.calls) <= 10.0 * res.c0 * (1 + 1e-9)


def test_batch_is_deterministic_and_ordered():
    wall = Wall(thickness=0.4, height=3.0, unit_weight=18e3)
    recs = [synthetic_record(seed, duration=6.0) for seed in range(4)]
    tasks = [
        IdaTask(RockingModel(wall, mech), r, 0.01)
        for mech in ("one-sided", "two-sided")
        for r in recs
    ]
    seen = []
    serial = run_batch(tasks, jobs=1, progress=lambda d, n: seen.append((d, n)))
    parallel = run_batch(tasks, jobs=2)
    assert [r.collapse_multiplier for r in serial] == [r.collapse_multiplier for r in parallel]
    assert seen[-1] == (len(tasks), len(tasks))
    direct = ida(tasks[5].model, tasks[5].acc, 0.01)
    assert serial[5].collapse_multiplier == direct.collapse_multiplier


def test_batch_cancel():
    wall = Wall(thickness=0.4, height=3.0, unit_weight=18e3)
    tasks = [
        IdaTask(RockingModel(wall, "one-sided"), synthetic_record(s, 6.0), 0.01) for s in range(6)
    ]
    stop = threading.Event()
    delivered = []

    def on_result(i, r):
        delivered.append(i)
        stop.set()

    with pytest.raises(Cancelled):
        run_batch(tasks, jobs=1, on_result=on_result, cancel=stop)
    assert delivered == [0]
