"""Response spectrum (Nigam & Jennings 1969 recurrence) against closed forms and an ODE solve.

* Step of acceleration a0 from rest, damping ξ: peak = a0·(1 + exp(−πξ/√(1−ξ²))) = 1.854468·a0
  at 5 % (Chopra, Dynamics of Structures, §4.3, step force with damping).
* Long resonant sine of amplitude A: steady-state pseudo-acceleration A/(2ξ) (Chopra §3.2).
* Brute force: scipy solve_ivp (rtol 1e-10) on the linearly interpolated record.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from frp_assess.motions.response import response_spectrum
from tests.conftest import synthetic_record


def test_step_overshoot():
    dt = 0.001
    acc = np.full(20001, 2.0)
    psa = response_spectrum(acc, dt, [0.2, 0.5, 1.0], 0.05)
    assert psa == pytest.approx(np.full(3, 1.854468 * 2.0), rel=1e-5)


def test_resonant_sine():
    T, xi, A, dt = 0.5, 0.05, 1.0, 0.0025
    t = np.arange(0, 120.0, dt)
    psa = response_spectrum(A * np.sin(2 * math.pi / T * t), dt, [T], xi)[0]
    assert psa == pytest.approx(A / (2 * xi), rel=2e-3)


def test_substeps_for_short_periods():
    """dt > T/40 triggers sub-steps: a coarse record gives the same as the exact step answer."""
    acc = np.full(2001, 1.0)
    assert response_spectrum(acc, 0.02, [0.05], 0.05)[0] == pytest.approx(1.854468, rel=1e-5)


def test_against_ode_solution():
    dt = 0.01
    acc = synthetic_record(7, duration=6.0, dt=dt)
    periods = np.array([0.1, 0.3, 0.7, 1.5])
    ours = response_spectrum(acc, dt, periods, 0.05)
    t = np.arange(acc.size) * dt
    for T, val in zip(periods, ours, strict=True):
        w = 2 * math.pi / T

        def f(tt, y, w=w):
            a = np.interp(tt, t, acc, right=0.0)
            return [y[1], -a - 2 * 0.05 * w * y[1] - w * w * y[0]]

        sol = solve_ivp(
            f,
            (0, t[-1] + T),
            [0.0, 0.0],
            rtol=1e-10,
            atol=1e-12,
            max_step=dt / 4,
            dense_output=True,
        )
        tt = np.linspace(0, t[-1] + T, 40001)
        ref = w * w * np.max(np.abs(sol.sol(tt)[0]))
        assert val == pytest.approx(ref, rel=4e-3)  # peak sampled at >= 40 points per period
