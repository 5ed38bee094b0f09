"""Similarity law of rocking (Makris & Vassiliou 2012; Dimitrakopoulos & DeJong 2012):
scaling the block size R by k and the time axis of the excitation by √k (same accelerations)
gives the same rotation history at the scaled times, since Eq. 10 depends on time only
through p·t with p² = 3g/(4R), and K depends on E·ρ/(w·H)·f(α) — kept by scaling E by k.
"""

from __future__ import annotations

import math

import pytest

from frp_assess.dynamics import IdaSettings, Rebars, RockingModel, Wall, ida
from tests.conftest import synthetic_record


@pytest.mark.parametrize("mechanism", ["one-sided", "two-sided"])
@pytest.mark.parametrize("reinforced", [False, True])
def test_similarity_law(mechanism, reinforced):
    k = 4.0
    small = Wall(thickness=0.3, height=2.5, unit_weight=18e3)
    big = Wall(thickness=0.3 * k, height=2.5 * k, unit_weight=18e3)
    bars_small = Rebars(46e9, 0.015, "external", 1.0) if reinforced else None
    bars_big = Rebars(46e9 * k, 0.015, "external", 1.0) if reinforced else None
    dt = 0.01
    acc = synthetic_record(seed=5, duration=8.0, dt=dt, pga_g=0.25)
    small_model = RockingModel(small, mechanism, bars_small)
    scale = 0.7 * ida(small_model, acc, dt, IdaSettings(tolerance=0.01)).collapse_multiplier
    a = small_model.run(acc, dt, scale, history=True)
    b = RockingModel(big, mechanism, bars_big).run(acc, dt * math.sqrt(k), scale, history=True)
    assert a.max_rotation > 0.05 * small.alpha
    assert b.max_rotation == pytest.approx(a.max_rotation, rel=1e-9)
    assert b.impacts == a.impacts
    assert b.history.theta == pytest.approx(a.history.theta, rel=1e-7, abs=1e-12)
