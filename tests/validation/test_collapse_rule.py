"""The `overturning` collapse rule (docs/model.md §3): the wall's fate is decided from its
energy, so it does not depend on how long the record is followed.

References: the free-rocking energy E = ½θ'² + V_s(θ) of a rigid block (Housner 1963; with
the bars' elastic energy of the paper's Eq. 6 added), whose barrier is V at the tipping angle
tan θ* = sin α/(cos α − K); and a long free vibration integrated under the `end-of-record`
rule, which follows the wall without deciding anything.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frp_assess.dynamics import IdaSettings, ModelOptions, Rebars, RockingModel, Wall, ida
from frp_assess.errors import NumericalError
from tests.conftest import synthetic_record

DT = 0.01
URM = RockingModel(Wall(0.4, 3.0, 18e3), "two-sided")
#: the issue's wall: 0.40 × 5.5 m, two-sided, GFRP centred 1.5 ‰ (K ≈ 1.8 ≥ cos α: the
#: intact bars never let it tip)
RESTRAINED = RockingModel(Wall(0.40, 5.5, 18e3), "two-sided", Rebars(46e9, 0.015, "centred", 1.5))


def still(n: int = 200) -> np.ndarray:
    return np.zeros(n)


def test_restrained_wall_cannot_tip_with_intact_bars() -> None:
    assert RESTRAINED.K >= math.cos(RESTRAINED.wall.alpha)


@pytest.mark.parametrize("model", [URM, RESTRAINED], ids=["unreinforced", "GFRP K>cos a"])
@pytest.mark.parametrize("seed", [3, 4, 5])
def test_multiplier_does_not_depend_on_the_tail(model: RockingModel, seed: int) -> None:
    """Appending 5 or 30 s of zero motion leaves every first-collapse multiplier unchanged."""
    acc = synthetic_record(seed=seed, duration=10.0, dt=DT)
    settings = IdaSettings(tolerance=1e-3)
    cs = [
        ida(model.with_options(free_vibration_tail=tail), acc, DT, settings).collapse_multiplier
        for tail in (0.0, 5.0, 30.0)
    ]
    assert cs[0] is not None
    assert cs[1] == pytest.approx(cs[0], rel=1e-12)
    assert cs[2] == pytest.approx(cs[0], rel=1e-12)


def test_restrained_wall_falls_only_after_a_rupture() -> None:
    acc = synthetic_record(seed=4, duration=10.0, dt=DT)
    res = ida(RESTRAINED, acc, DT, IdaSettings(tolerance=1e-3))
    assert res.collapse_multiplier is not None
    run = RESTRAINED.run(acc, DT, res.collapse_multiplier)
    assert run.fate == "fell" and run.ruptures


@pytest.mark.parametrize(
    ("model", "label"),
    [(URM, "unreinforced"), (RESTRAINED, "GFRP")],
)
def test_at_rest_verdict_agrees_with_a_long_free_vibration(model: RockingModel, label: str) -> None:
    """Where the rule stops ("at rest"), a 60 s free vibration under the non-deciding
    `end-of-record` rule never falls, and its peak equals the energy-based peak."""
    acc = synthetic_record(seed=5, duration=10.0, dt=DT)
    c = ida(model, acc, DT, IdaSettings(tolerance=1e-3)).survivor_multiplier
    assert c is not None
    decided = model.run(acc, DT, c)
    followed = model.with_options(collapse="end-of-record", free_vibration_tail=60.0).run(
        acc, DT, c
    )
    assert decided.fate == "at rest"
    assert followed.fate == "standing" and abs(followed.final_theta) < model.wall.alpha
    assert decided.max_rotation == pytest.approx(followed.max_rotation, rel=1e-6)


def test_release_below_and_above_the_tipping_angle() -> None:
    """A block released from rest at θ0 in still air falls iff θ0 > θ* (here θ* = α)."""
    alpha = URM.wall.alpha
    below = URM.run(still(), DT, theta0=alpha * (1 - 1e-6))
    above = URM.run(still(), DT, theta0=alpha * (1 + 1e-6))
    assert below.fate == "at rest" and below.max_rotation == pytest.approx(alpha * (1 - 1e-6))
    assert above.fate == "fell"


def test_tipping_angle_with_bars() -> None:
    """With K < cos α the intact bars hold the wall up to tan θ* = sin α/(cos α − K) > α."""
    wall = Wall(0.4, 3.0, 18e3)
    bars = Rebars(46e9, 0.015, "centred", 0.05, strain_factor=1.0)
    model = RockingModel(wall, "one-sided", bars, ModelOptions(rupture="velocity-continuous"))
    a, k = wall.alpha, model.K
    assert k < math.cos(a)
    theta_star = math.atan2(math.sin(a), math.cos(a) - k)
    assert a < theta_star < model.theta_max
    below = model.run(still(), DT, theta0=theta_star * (1 - 1e-6))
    above = model.run(still(), DT, theta0=theta_star * (1 + 1e-6))
    assert below.fate == "at rest" and not below.ruptures
    assert above.fate == "fell"


def test_energy_reaching_rupture_is_not_at_rest() -> None:
    """A wall with enough energy to reach θ_max is not called at rest: the bar breaks first."""
    bars = Rebars(46e9, 0.015, "centred", 1.0)
    model = RockingModel(Wall(0.4, 3.0, 18e3), "one-sided", bars)
    theta_max = model.theta_max
    res = model.run(still(), DT, theta0=theta_max * 0.999, omega0=5.0)
    assert len(res.ruptures) == 1
    assert res.max_rotation >= theta_max


def test_balanced_on_its_edge_is_an_error_not_a_guess() -> None:
    """Released exactly at θ = α with no velocity the block sits on its unstable equilibrium:
    its energy equals the barrier, so the fate is never certain; after the bounded free
    vibration (300 s) the kernel says so instead of guessing a verdict."""
    with pytest.raises(NumericalError, match="not certain after 300 s of free vibration"):
        URM.run(still(10), DT, theta0=URM.wall.alpha)
