"""Response spectrum by the Nigam & Jennings (1969) recurrence (frp_assess.motions.response)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from frp_assess.motions.response import response_spectrum


@pytest.mark.parametrize("period", [0.02, 0.1, 0.5, 2.0])
def test_step_response(period):
    """A step a0 from rest: peak u = a0/ω²·(1 + exp(−πξ/√(1−ξ²))), i.e. PSA = 1.854468·a0 at 5 %."""
    a0 = 2.5
    acc = np.full(int(4 * period / 0.005) + 2, a0)
    psa = response_spectrum(acc, 0.005, [period], damping=0.05)[0]
    assert psa == pytest.approx(1.854468 * a0, rel=2e-5)


@pytest.mark.parametrize("xi", [0.02, 0.05, 0.10])
def test_step_response_other_damping(xi):
    psa = response_spectrum(np.ones(801), 0.01, [1.0], damping=xi)[0]
    assert psa == pytest.approx(1 + math.exp(-math.pi * xi / math.sqrt(1 - xi * xi)), rel=1e-5)


@pytest.mark.parametrize("period,xi", [(0.3, 0.05), (1.0, 0.05), (1.0, 0.02)])
def test_resonant_sine_tends_to_a_over_2xi(period, xi):
    """Steady state at resonance: u = A/(2ξω²), so PSA → A/(2ξ).  The sine is sampled at
    T/200 (linear interpolation between samples attenuates it by sinc², here 8e-5) and lasts
    8/(ξω) so the transient has decayed to e⁻⁸."""
    dt = period / 200
    t = np.arange(0.0, 8.0 / (xi * 2 * math.pi / period), dt)
    acc = 0.7 * np.sin(2 * math.pi / period * t)
    psa = response_spectrum(acc, dt, [period], damping=xi)[0]
    assert psa == pytest.approx(0.7 / (2 * xi), rel=1e-3)


def test_zero_period_is_pga_and_padding_catches_late_peak():
    acc = np.zeros(11)
    acc[-1] = 1.0  # the record ends at its peak: the oscillator peaks after the end
    psa = response_spectrum(acc, 0.01, [0.0, 2.0])
    assert psa[0] == 1.0
    # brute force over the zero-padded record (linear ramp, then free vibration)
    padded = np.concatenate([acc, np.zeros(400)])
    assert psa[1] == pytest.approx(_brute_force(padded, 0.01, 2.0, 0.05), rel=1e-4)
    assert psa[1] > 0.0


def _brute_force(acc: np.ndarray, dt: float, period: float, xi: float) -> float:
    """PSA by scipy's RK45 at tight tolerances on the piecewise-linear input, fine sampling.

    The input (linear between samples, zero after the last one) is integrated one sample
    interval at a time, each a smooth problem, the state carried across: RK45 then needs no
    tiny steps at the kinks (over the whole record at once it cost 9 s for this file)."""
    w = 2 * math.pi / period
    t_rec = np.arange(acc.size) * dt
    spacing = min(dt, period) / 200  # the fine sampling the peak is read from
    pieces = [(t_rec[k], t_rec[k + 1], acc[k], acc[k + 1]) for k in range(acc.size - 1)]
    pieces.append((t_rec[-1], t_rec[-1] + period, 0.0, 0.0))  # free vibration after the end
    y = np.zeros(2)
    peak = 0.0
    for t0, t1, a0, a1 in pieces:
        slope = (a1 - a0) / (t1 - t0)

        def rhs(t, state, a0=a0, t0=t0, slope=slope):
            ag = a0 + slope * (t - t0)
            return [state[1], -ag - 2 * xi * w * state[1] - w * w * state[0]]

        t_eval = np.linspace(t0, t1, max(2, math.ceil((t1 - t0) / spacing) + 1))
        sol = solve_ivp(
            rhs, (t0, t1), y, t_eval=t_eval, rtol=1e-10, atol=1e-13, max_step=period / 20
        )
        peak = max(peak, float(np.max(np.abs(sol.y[0]))))
        y = sol.y[:, -1]
    return w * w * peak


@pytest.mark.slow
def test_agrees_with_brute_force_ode():
    """Random record; periods below and above 10·dt (sub-stepping) and damping 2 %, 5 %."""
    rng = np.random.default_rng(42)
    acc = rng.standard_normal(151) * 3.0
    dt = 0.01
    periods = np.array([0.03, 0.07, 0.25, 1.0])
    for xi in (0.02, 0.05):
        fast = response_spectrum(acc, dt, periods, damping=xi)
        slow = np.array([_brute_force(acc, dt, T, xi) for T in periods])
        np.testing.assert_allclose(fast, slow, rtol=1e-3)


def test_rejects_bad_arguments():
    with pytest.raises(ValueError):
        response_spectrum([1.0, 2.0], 0.01, [1.0], damping=1.0)
    with pytest.raises(ValueError):
        response_spectrum([1.0, 2.0], 0.0, [1.0])
    with pytest.raises(ValueError):
        response_spectrum([1.0, 2.0], 0.01, [-1.0])


def _one_oscillator(acc: np.ndarray, dt: float, period: float, xi: float) -> tuple[float, int]:
    """The recurrence for one period alone, in plain Python, as the module first wrote it:
    every (sub-)step checked for a velocity sign change and its Hermite peak taken.  Returns
    (PSA, how many times a Hermite peak raised the maximum)."""
    from frp_assess.motions.response import _coefficients, _hermite_peak

    omega = 2.0 * math.pi / period
    nsub = max(1, math.ceil(10.0 * dt / period - 1e-9))
    h = dt / nsub
    a, b, c, d, ap, bp, cp, dp = _coefficients(omega, xi, h)
    n = acc.size
    u = v = umax = 0.0
    raised = 0
    for i in range(n - 1 + math.ceil(period / dt) + 1):
        a0 = float(acc[i]) if i < n else 0.0
        a1 = float(acc[i + 1]) if i + 1 < n else 0.0
        for m in range(nsub):
            p0 = -(a0 + (a1 - a0) * m / nsub)
            p1 = -(a0 + (a1 - a0) * (m + 1) / nsub)
            un = a * u + b * v + c * p0 + d * p1
            vn = ap * u + bp * v + cp * p0 + dp * p1
            umax = max(umax, abs(un))
            if v * vn < 0.0:
                peak = _hermite_peak(u, v, un, vn, h)
                if peak > umax:
                    umax = peak
                    raised += 1
            u, v = un, vn
    return omega * omega * umax, raised


def test_the_periods_side_by_side_equal_each_period_alone():
    """The spectrum advances all oscillators of a record together and evaluates the Hermite
    peak only where it can exceed the maximum so far (a bound of the cubic); each period's
    PSA must equal, to the last bit, the recurrence for that period alone with the peak
    taken at every sign change (written here in plain Python).  The cases include sub-steps
    (T < 10·dt), the free vibration after the record, zero damping, and steps where the
    Hermite peak is what sets the maximum (counted, so the check is not vacuous)."""
    rng = np.random.default_rng(11)
    raised = 0
    for dt, xi in ((0.01, 0.05), (0.02, 0.0), (0.005, 0.2)):
        acc = rng.normal(size=400) * np.hanning(400)
        periods = np.array([0.0, 0.015, 0.03, 0.07, 0.1, 0.37, 1.0, 2.5, 0.03, 0.6])
        got = response_spectrum(acc, dt, periods, damping=xi)
        for T, value in zip(periods, got, strict=True):
            if T == 0.0:
                assert value == np.max(np.abs(acc))
                continue
            expected, count = _one_oscillator(acc, dt, float(T), xi)
            raised += count
            assert value == expected, (dt, xi, T)
    assert raised > 0


def test_the_kernels_get_a_read_only_record_whatever_the_caller_passes(monkeypatch):
    """A writable and a read-only array are two argument types for numba, so the spectra's
    kernel was compiled twice (2 CPU-s on a cold cache): response_spectrum and the floor
    filter hand their kernels a read-only view of a writable input (which stays writable)."""
    from frp_assess.motions import floor, response

    seen = []

    def spy(module, name):
        kernel = getattr(module, name)

        def call(acc, *args):
            seen.append((name, acc.flags.writeable))
            return kernel(acc, *args)

        monkeypatch.setattr(module, name, call)

    spy(response, "_psa")
    spy(floor, "_relative_acceleration")
    acc = np.sin(np.arange(400) * 0.1)
    assert acc.flags.writeable
    sa = response_spectrum(acc, 0.01, [0.2, 0.5])
    a_floor = floor.floor_acceleration(
        acc, 0.01, height_building=9.0, storeys=3, wall_base=6.0, period=0.3
    )
    assert seen == [("_psa", False), ("_relative_acceleration", False)]
    assert acc.flags.writeable
    assert sa.shape == (2,) and np.all(sa > 0.0) and a_floor.shape == acc.shape
