"""The independent checks of NTC 2018 §10.2 (frp_assess.assess.independent_checks): they pass
on the model as it is and each fails when the model is deliberately broken.

Hand calculation of the wall below (the Circolare's moment balance about the crushing pivot):
W = γ·B·H = 18e3 · 0.25 · 4.5 = 20 250 N/m; x = W/(0.85·f_d) = 20 250/(0.85 · 2.875e6) =
8.286 mm; α₀ = (B − x)/H = (0.25 − 0.008286)/4.5 = 0.053714.
"""

from __future__ import annotations

import numpy as np
import pytest

import frp_assess.dynamics.rocking as rocking
from frp_assess.assess import independent_checks as ic
from frp_assess.dynamics import RockingModel, Wall
from frp_assess.motions import Record

WALL = Wall(thickness=0.25, height=4.5, unit_weight=18e3, compressive_strength=2.875e6)


def model(mechanism: str = "one-sided") -> RockingModel:
    return RockingModel(WALL, mechanism)  # type: ignore[arg-type]


def record() -> Record:
    """A smoothed white noise, 25 s at 0.005 s, about 0.25 g peak (seeded)."""
    rng = np.random.default_rng(1)
    acc = np.convolve(rng.normal(0.0, 3.0, 5000), np.ones(20) / 20, "same")
    return Record("noise", 0.005, acc)


def test_hand_alpha0_is_the_circolare_moment_balance():
    alpha0, depth = ic.hand_alpha0(model())
    assert depth == pytest.approx(20250 / (0.85 * 2.875e6), rel=1e-12)
    assert alpha0 == pytest.approx(0.053714, abs=5e-7)


@pytest.mark.parametrize("mechanism", ["one-sided", "two-sided"])
def test_every_check_passes_on_the_model_as_it_is(mechanism):
    m = model(mechanism)
    checks = [
        ic.activation_check(m),
        ic.period_check(m),
        ic.impact_check(m),
        ic.reference_check(m, record(), "noise", "URM", 1.0),
    ]
    for c in checks:
        assert c.passed, c.detail
        assert c.deviation <= c.tolerance


def test_a_wrong_restitution_in_the_kernel_fails_the_energy_check(monkeypatch):
    """The kernel's velocity ratio 5 % low (as a wrong Eq. 14 would give): the rebound after
    the first impact is lower than the energy balance with Housner's coefficient says."""
    true = rocking.velocity_ratio
    monkeypatch.setattr(rocking, "velocity_ratio", lambda *a: 0.95 * true(*a))
    m = model()
    impact = ic.impact_check(m)
    assert not impact.passed and impact.deviation > 5 * impact.tolerance
    assert ic.activation_check(m).passed and ic.period_check(m).passed


def test_a_wrong_activation_acceleration_fails_the_alpha0_check(monkeypatch):
    """a_RM 2 % high (a base reaction at the wrong depth): the hand α₀ disagrees."""
    true = rocking.RockingModel.a_rm
    monkeypatch.setattr(rocking.RockingModel, "a_rm", property(lambda s: 1.02 * true.fget(s)))
    check = ic.activation_check(model())
    assert not check.passed and check.deviation == pytest.approx(0.02, rel=1e-9)
