"""Free rocking of the rigid block, against closed forms.

Sources:
* Housner, G.W. (1963) BSSA 53(2): rocking period from energy conservation,
  T = 4∫₀^θ0 dθ / √(2p²[cos(α−θ0) − cos(α−θ)]) (exact, not linearised), and the impact
  energy ratio r = (1 − 1.5 sin²α)² (paper Eq. 13).
* Energy argument for the decay per impact: with velocity ratio e,
  cos(α−θₙ₊₁) − cos α = e²[cos(α−θₙ) − cos α].
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from frp_assess.dynamics import ModelOptions, RockingModel, Wall, velocity_ratio

WALL = Wall(thickness=0.4, height=3.0, unit_weight=18e3)


def exact_period(wall: Wall, theta0: float) -> float:
    a, p2 = wall.alpha, wall.p2

    # θ = θ0 − v² removes the 1/√(θ0 − θ) singularity: dθ = −2v dv
    def integrand(v: float) -> float:
        th = theta0 - v * v
        return 2 * v / math.sqrt(2 * p2 * (math.cos(a - theta0) - math.cos(a - th)))

    val, _ = quad(integrand, 0.0, math.sqrt(theta0), epsabs=1e-13, epsrel=1e-12, limit=200)
    return 4 * val


def crossing_times(time: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """Zero crossings of θ(t), linearly interpolated between samples."""
    ok = ~np.isnan(theta)
    time, theta = time[ok], theta[ok]
    idx = np.nonzero(np.sign(theta[:-1]) * np.sign(theta[1:]) < 0)[0]
    return time[idx] - theta[idx] * (time[idx + 1] - time[idx]) / (theta[idx + 1] - theta[idx])


@pytest.mark.parametrize("ratio", [0.1, 0.5, 0.9])
def test_free_rocking_period(ratio):
    """Release from θ0 = ratio·α with no energy loss (velocity ratio 1): impacts every T/2,
    the first after T/4."""
    theta0 = ratio * WALL.alpha
    model = RockingModel(WALL, "two-sided", options=ModelOptions(restitution=1.0))
    dt = 0.0005
    T = exact_period(WALL, theta0)
    acc = np.zeros(int(2.2 * T / dt))
    res = model.run(acc, dt, history=True, theta0=theta0)
    tc = crossing_times(res.history.time, res.history.theta)
    assert len(tc) >= 4
    assert tc[0] == pytest.approx(T / 4, rel=2e-5)
    assert np.diff(tc) == pytest.approx(np.full(len(tc) - 1, T / 2), rel=2e-5)
    assert res.max_rotation == pytest.approx(theta0, rel=1e-9)


def local_amplitudes(theta: np.ndarray) -> np.ndarray:
    """Largest |θ| in each excursion between zero crossings (sampled finely)."""
    theta = theta[~np.isnan(theta)]
    sign = np.sign(theta)
    out, cur = [], 0.0
    for k in range(1, len(theta)):
        if sign[k] != sign[k - 1] and sign[k] != 0:
            out.append(cur)
            cur = 0.0
        cur = max(cur, abs(theta[k]))
    return np.array(out)


@pytest.mark.parametrize("mechanism", ["two-sided", "one-sided"])
def test_amplitude_decay_per_impact(mechanism):
    wall = WALL
    e = velocity_ratio("energy", mechanism, wall.alpha)
    theta0 = 0.8 * wall.alpha
    model = RockingModel(wall, mechanism)
    dt = 0.0002
    res = model.run(np.zeros(int(8.0 / dt)), dt, history=True, theta0=theta0)
    th = res.history.theta
    if mechanism == "one-sided":
        # θ ≥ 0: each excursion after an impact has one local maximum
        inner = th[1:-1]
        amps = inner[(inner > th[:-2]) & (inner >= th[2:])][:4]
    else:
        amps = local_amplitudes(th)[1:5]
    a = wall.alpha
    prev = theta0
    assert len(amps) >= 3
    for amp in amps:
        expected = math.acos(math.cos(a) + e * e * (math.cos(a - prev) - math.cos(a)))
        expected = a - expected
        assert amp == pytest.approx(expected, rel=1e-4)
        prev = amp
