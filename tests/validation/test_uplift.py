"""Uplift from rest: a rigid block starts rocking when the ground acceleration exceeds g·tan α.

Source: Housner, G.W. (1963) "The behavior of inverted pendulum structures during
earthquakes", BSSA 53(2) — the static overturning condition ü_g > g·B/H; docs/model.md §3 (uplift).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frp_assess.dynamics import Rebars, RockingModel, Wall

G = 9.80665
WALL = Wall(thickness=0.4, height=3.0, unit_weight=18e3)


def pulse(level_g: float, dt: float = 0.001, hold: float = 1.0) -> np.ndarray:
    """Ramp to ``level_g`` (g) in 0.1 s, hold, ramp down: [m/s²]."""
    n_ramp = int(0.1 / dt)
    n_hold = int(hold / dt)
    shape = np.concatenate([np.linspace(0, 1, n_ramp), np.ones(n_hold), np.linspace(1, 0, n_ramp)])
    return level_g * G * shape


@pytest.mark.parametrize("mechanism", ["one-sided", "two-sided"])
@pytest.mark.parametrize("rebars", [None, Rebars(150e9, 0.013, "external", 2.0)])
def test_no_motion_just_below_threshold(mechanism, rebars):
    model = RockingModel(WALL, mechanism, rebars)
    res = model.run(pulse(-0.999 * WALL.a_rm_g), 0.001)
    assert res.max_rotation == 0.0 and res.impacts == 0


@pytest.mark.parametrize("mechanism", ["one-sided", "two-sided"])
@pytest.mark.parametrize("rebars", [None, Rebars(150e9, 0.013, "external", 2.0)])
def test_motion_just_above_threshold(mechanism, rebars):
    """Bars are unstressed at rest, so they do not change a_RM (docs/model.md §3)."""
    model = RockingModel(WALL, mechanism, rebars)
    res = model.run(pulse(-1.01 * WALL.a_rm_g), 0.001, history=True)
    assert res.max_rotation > 0.0
    # ü_g < 0 lifts the wall to θ > 0 (a two-sided wall may later swing through θ = 0)
    first_move = np.nonzero(res.history.theta)[0][0]
    assert res.history.theta[first_move] > 0.0
    if mechanism == "one-sided":
        assert np.nanmin(res.history.theta) >= 0.0


def test_one_sided_never_rotates_into_the_restraint():
    """One-sided: only θ ≥ 0; a push towards the restraint moves nothing."""
    model = RockingModel(WALL, "one-sided")
    toward = model.run(pulse(+3.0 * WALL.a_rm_g), 0.001)
    assert toward.max_rotation == 0.0
    dt = 0.002
    t = np.arange(0, 6, dt)
    acc = 2.5 * WALL.a_rm * np.sin(2 * math.pi * 1.5 * t)
    res = model.run(acc, dt, history=True)
    assert res.max_rotation > 0.0
    assert np.nanmin(res.history.theta) >= 0.0


def test_two_sided_rocks_both_ways():
    model = RockingModel(WALL, "two-sided")
    res = model.run(pulse(+1.05 * WALL.a_rm_g), 0.001, history=True)
    assert np.nanmin(res.history.theta) < 0.0
    assert np.nanmax(res.history.theta) <= 0.0
