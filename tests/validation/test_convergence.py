"""Convergence under step halving (MODEL.md §4): halving the internal step changes the peak
rotation by < 0.1 % and the collapse multiplier by < 0.2 %.

Records: seeded synthetic band-limited noise (tests/conftest.py), 10 s at dt = 0.01 s.

Measured caveat (kept out of the asserts, stated here): a *two-sided unreinforced* wall
driven close to its collapse boundary is chaotic — it chatters at |θ| ~ 1e-7 rad and
differences of 1e-14 rad grow to O(1) within seconds, so for about 1 record in 20 the first
collapse multiplier changes by > 1 % between any two step sizes (or integrators), without
converging monotonically.  One-sided and restrained walls agree to 4 digits at every step
tried.  The peak-rotation check therefore runs at 0.6·C, away from that boundary.
"""

from __future__ import annotations

import pytest

from frp_assess.dynamics import IdaSettings, ida
from tests.conftest import synthetic_record
from tests.validation.configs import CASES, model_for

DT = 0.01


@pytest.mark.parametrize("name", list(CASES))
def test_peak_rotation_converges(name):
    acc = synthetic_record(seed=11, duration=10.0, dt=DT)
    base = model_for(name)
    h = DT / base.substeps(DT)
    finer = model_for(name, max_step=h / 2)
    assert finer.substeps(DT) == 2 * base.substeps(DT)
    # a scale that makes the wall rock hard without falling
    res = ida(base, acc, DT, IdaSettings(tolerance=0.01))
    scale = 0.6 * res.collapse_multiplier
    a = base.run(acc, DT, scale)
    b = finer.run(acc, DT, scale)
    assert a.max_rotation > 0.05 * base.wall.alpha
    assert abs(a.max_rotation - b.max_rotation) <= 1e-3 * b.max_rotation


@pytest.mark.parametrize("name", list(CASES))
def test_collapse_multiplier_converges(name):
    acc = synthetic_record(seed=12, duration=10.0, dt=DT)
    fine_ida = IdaSettings(tolerance=1e-4)
    base = model_for(name)
    finer = model_for(name, max_step=DT / base.substeps(DT) / 2)
    ca = ida(base, acc, DT, fine_ida).collapse_multiplier
    cb = ida(finer, acc, DT, fine_ida).collapse_multiplier
    assert ca is not None and cb is not None
    assert abs(ca - cb) <= 2e-3 * cb
