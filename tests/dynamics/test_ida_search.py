"""The compiled IDA search (frp_assess/dynamics/ida_search.py): the rule of docs/model.md §5,
the quiet start it skips, and bit-for-bit equality with one ``RockingModel.run`` per time
history from the record's first sample."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from frp_assess.dynamics import IdaSettings, RockingModel, ida
from frp_assess.dynamics.ida_search import next_multiplier, quiet_intervals, running_max_abs
from frp_assess.dynamics.kernel import Buffers, Ground, simulate
from frp_assess.dynamics.kernel.params import NO_TIES, kernel_record
from tests.conftest import G, synthetic_record
from tests.dynamics.walls import CFRP, SIX_WALLS, WALL


def _quiet_start(seed: int, quiet_s: float = 2.0, dt: float = 0.01) -> np.ndarray:
    """A synthetic record after ``quiet_s`` seconds of weak motion (1 % of its PGA)."""
    rec = synthetic_record(seed, duration=6.0, dt=dt)
    lead = 0.01 * np.max(np.abs(rec)) * np.sin(np.arange(int(quiet_s / dt)) * 0.3)
    return np.concatenate([lead, rec])


def test_quiet_intervals_counts_by_hand():
    """Threshold g·tan α_x/C = 0.5 m/s²: samples 0.1, −0.2, 0.3 are below it, −0.6 is not, so
    intervals 0 and 1 cannot uplift and interval 2 ([0.3, −0.6]) may: 2 quiet intervals."""
    prm = RockingModel(WALL, "two-sided").params
    acc = np.array([0.1, -0.2, 0.3, -0.6, 0.2, 1.0])
    peaks = running_max_abs(acc)
    assert list(peaks) == [0.1, 0.2, 0.3, 0.6, 0.6, 1.0]
    c = prm.g * prm.tan_ax / 0.5
    assert quiet_intervals(peaks, c, prm) == 2
    # a sample exactly at the threshold may uplift (the margin keeps it): still 2
    assert quiet_intervals(peaks, prm.g * prm.tan_ax / 0.6, prm) == 2
    # nothing reaches the threshold: all but the last interval are quiet
    assert quiet_intervals(peaks, prm.g * prm.tan_ax / 2.0, prm) == 4
    # the first sample already reaches it: none
    assert quiet_intervals(peaks, prm.g * prm.tan_ax / 0.05, prm) == 0


def test_next_multiplier_is_the_rule_of_the_model():
    """docs/model.md §5 by hand: hunt 1, 1.1, 1.21 (s = 1.1), tolerance 0.005."""
    hunt = np.array([1.0, 1.1, 1.21])
    assert next_multiplier(hunt, 0.005, 0, 0.0, math.nan) == 1.0
    assert next_multiplier(hunt, 0.005, 2, 1.1, math.nan) == 1.21
    assert math.isnan(next_multiplier(hunt, 0.005, 3, 1.21, math.nan))  # C_max: no collapse
    assert next_multiplier(hunt, 0.005, 3, 1.1, 1.21) == 0.5 * (1.1 + 1.21)
    # 1.205 − 1.2 = 0.005 ≤ 0.005·1.205: over
    assert math.isnan(next_multiplier(hunt, 0.005, 6, 1.2, 1.205))


@pytest.mark.parametrize("mechanism, bars, options", SIX_WALLS)
def test_compiled_search_equals_one_run_per_time_history(mechanism, bars, options):
    """The same IdaResult, bit for bit (floats compared with ==), from the compiled search
    (quiet start skipped) and from one ``run`` per time history over the whole record."""
    model = RockingModel(WALL, mechanism, bars).with_options(**options)
    settings = IdaSettings(max_multiplier=20.0)
    for seed in range(3):
        acc = _quiet_start(seed)
        compiled = ida(model, acc, 0.01, settings)
        per_run = ida(model, acc, 0.01, settings, compiled=False)
        assert compiled == per_run
        assert compiled.runs >= 3


def test_a_time_history_from_its_quiet_start_is_the_same_numbers():
    """The kernel started at the first interval that may uplift, from rest, computes the same
    peak, final state, events and even the same integration steps as from sample 0."""
    model = RockingModel(WALL, "two-sided", CFRP)
    prm = model.params
    acc = kernel_record(_quiet_start(7))  # the array type the product passes
    c = 1.5 * model.a_rm / np.max(np.abs(acc))
    start = quiet_intervals(running_max_abs(acc), c, prm)
    assert start >= 150  # 2 s of weak motion at dt = 0.01 s are skipped
    # the skipped intervals really are below the uplift threshold g·tan α_x
    assert np.max(np.abs(acc[: start + 1])) * c < G * prm.tan_ax

    def run(a: np.ndarray) -> Any:
        h = np.empty(1)
        buf = Buffers(h, h, h, np.zeros(2), np.zeros(2, np.int64))
        return simulate(Ground(a, 0.01, c, 0), prm, NO_TIES, 0.0, 0.0, False, buf)

    full, skipped = run(acc), run(acc[start:])
    for name in ("status", "fate", "peak", "peak_with_bar", "impacts", "ruptures"):
        assert getattr(skipped, name) == getattr(full, name), name
    for name in ("final_theta", "final_omega", "steps", "rejected"):
        assert getattr(skipped, name) == getattr(full, name), name
    assert full.steps > 100  # it rocked
