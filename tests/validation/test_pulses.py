"""Overturning of a slender block by rectangular and half-sine pulses (linearised closed forms).

Source: Housner, G.W. (1963) BSSA 53(2), the pulse analysis of §"Rectangular pulse";
derivation (small α, sin(α−θ) ≈ α−θ, cos ≈ 1), written out here:

* While rocking (s = +1) under ü_g = −β·g·α: θ'' = p²θ + p²α(β − 1).  From rest,
  θ = α(β−1)(cosh pt − 1).  After the pulse θ'' = p²(θ − α), whose stable manifold shows that
  the block reaches θ = α (and falls) iff (θ − α) + θ'/p ≥ 0 when the pulse ends.
* Rectangular pulse of length t_p, τ = p·t_p:  (β−1)(e^τ − 1) ≥ 1, i.e. β_min = 1/(1 − e^−τ).
* Half-sine ü_g = −β·g·α·sin(ω_p t): uplift at t0 = asin(1/β)/ω_p, then
  θ = α − A sin ω_p t + c1 cosh p(t−t0) + c2 sinh p(t−t0), A = αβp²/(p² + ω_p²),
  c1 = −(α − A sin ω_p t0), c2 = A(ω_p/p) cos ω_p t0; the threshold β_min solves the same
  manifold condition at t = π/ω_p (overturning without an impact, Housner's "mode 1").
At α = 0.02 rad the linearisation error is O(α²) ≈ 4e-4, far inside the ±2–3 % brackets tested.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from frp_assess.dynamics import ModelOptions, RockingModel, Wall

G = 9.80665
ALPHA = 0.02
WALL = Wall.from_slenderness(3.0, ALPHA, 18e3)
P = WALL.p


def rectangular_threshold(tau: float) -> float:
    return 1.0 / (1.0 - math.exp(-tau))


def half_sine_end_state(beta: float, wp: float) -> tuple[float, float]:
    a, p = ALPHA, P
    t0 = math.asin(1.0 / beta) / wp
    A = a * beta * p**2 / (p**2 + wp**2)
    c1 = -(a - A * math.sin(wp * t0))
    c2 = A * wp / p * math.cos(wp * t0)
    te = math.pi / wp
    d = p * (te - t0)
    theta = a - A * math.sin(wp * te) + c1 * math.cosh(d) + c2 * math.sinh(d)
    omega = -A * wp * math.cos(wp * te) + p * (c1 * math.sinh(d) + c2 * math.cosh(d))
    return theta, omega


def half_sine_threshold(wp: float) -> float:
    def margin(beta: float) -> float:
        theta, omega = half_sine_end_state(beta, wp)
        return theta - ALPHA + omega / P

    return brentq(margin, 1.0 + 1e-9, 200.0, xtol=1e-12)


def run(acc: np.ndarray, dt: float, collapse: str = "end-of-record"):
    model = RockingModel(
        WALL, "one-sided", options=ModelOptions(free_vibration_tail=20.0, collapse=collapse)
    )
    return model.run(acc, dt)


@pytest.mark.parametrize("tau", [0.3, 1.0, 3.0])
def test_rectangular_pulse_threshold(tau):
    t_p = tau / P
    dt = t_p / 2000
    n = int(round(t_p / dt))
    beta_min = rectangular_threshold(tau)
    for factor, falls in [(1.02, True), (0.98, False)]:
        acc = np.zeros(n + 2)
        acc[: n + 1] = -factor * beta_min * G * ALPHA
        assert run(acc, dt).collapsed is falls, (tau, factor)


@pytest.mark.parametrize("wp_over_p", [2.0, 5.0])
def test_half_sine_pulse_threshold(wp_over_p):
    wp = wp_over_p * P
    beta_min = half_sine_threshold(wp)
    t_e = math.pi / wp
    dt = t_e / 4000
    t = np.arange(0, t_e + dt / 2, dt)
    model = RockingModel(
        WALL,
        "one-sided",
        options=ModelOptions(collapse="first-exceedance", free_vibration_tail=20.0),
    )
    above = model.run(-1.03 * beta_min * G * ALPHA * np.sin(wp * t), dt)
    assert above.collapsed and above.impacts == 0
    below = model.run(-0.97 * beta_min * G * ALPHA * np.sin(wp * t), dt)
    assert (not below.collapsed) or below.impacts >= 1


def test_half_sine_state_at_pulse_end():
    """The kernel's (θ, θ') at the end of a sub-threshold half-sine matches the closed form."""
    wp = 3.0 * P
    beta = 0.9 * half_sine_threshold(wp)
    t_e = math.pi / wp
    n = 4000
    dt = t_e / n
    t = np.arange(n + 1) * dt
    res = RockingModel(WALL, "one-sided").run(-beta * G * ALPHA * np.sin(wp * t), dt, history=True)
    theta, omega = half_sine_end_state(beta, wp)
    assert res.history.theta[-1] == pytest.approx(theta, rel=2e-3)
    assert res.history.omega[-1] == pytest.approx(omega, rel=2e-3, abs=1e-4 * P * ALPHA)
