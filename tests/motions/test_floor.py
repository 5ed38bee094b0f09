"""Floor motion and floor spectrum (frp_assess.motions.floor).

Expected values are worked out here, by hand, from the clauses: Circolare 2019 §C7.2.3
(eqs. C7.2.5-C7.2.10), §C7.3.3.2 (eq. C7.3.2) and §C8.7.1.2.1.8 (eq. C8.7.1.12).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frp_assess.motions.floor import (
    default_period,
    floor_acceleration,
    floor_displacement_spectrum,
    floor_spectrum,
    ground_displacement_spectrum,
    ground_spectrum_function,
    participation_factor,
)
from frp_assess.motions.response import response_spectrum
from frp_assess.motions.spectra import ec8_spectrum

G = 9.80665


def test_sine_through_the_building_matches_the_closed_form_steady_state():
    """eq. C7.2.10 filter: 1 Hz sine, T1 = 0.5 s, ξ1 = 20 %, n = 3, Z = H_b (ψ1 = 1).

    Steady state of u'' + 2ξωu' + ω²u = −A·sin Ωt: u = Im[U·e^{iΩt}], U = −A/(ω² − Ω² + 2iξωΩ),
    so a_floor = A·sin Ωt − γ1·Ω²·u = Im[A·(1 + γ1·Ω²/(ω² − Ω² + 2iξωΩ))·e^{iΩt}].
    The transient decays as e^{−ξωt}: e^{−20} after 8 s, when the comparison starts.
    """
    amp, big_omega = 1.7, 2 * math.pi  # 1 Hz
    omega, xi, gamma = 2 * math.pi / 0.5, 0.2, 9 / 7  # γ1 = 3·3/(2·3 + 1)
    dt = 0.001
    t = np.arange(0.0, 12.0 + dt / 2, dt)
    acc = amp * np.sin(big_omega * t)
    got = floor_acceleration(
        acc, dt, height_building=9.0, storeys=3, wall_base=9.0, period=0.5, damping=xi
    )
    h = 1 + gamma * big_omega**2 / (omega**2 - big_omega**2 + 2j * xi * omega * big_omega)
    expected = np.imag(amp * h * np.exp(1j * big_omega * t))
    late = t >= 8.0
    assert abs(h) > 1.3  # the building amplifies: the check is not a copy of the input
    np.testing.assert_allclose(got[late], expected[late], rtol=0, atol=2e-5 * amp)


def test_wall_at_ground_level_gets_the_ground_record_back_exactly(record_factory):
    """Z = 0: ψ1 = 0, a_floor = ü_g (eq. C7.2.10 mode)."""
    acc = record_factory(3)
    got = floor_acceleration(
        acc, 0.01, height_building=12.0, storeys=4, wall_base=0.0, period=0.32, damping=0.05
    )
    assert np.array_equal(got, acc)
    assert got is not acc


def test_floor_motion_uses_the_oscillator_of_the_response_spectrum(record_factory):
    """ξ1 = 0: the oscillator's absolute acceleration ü_g + D̈1 = −ω²u, so its peak over the
    samples (the record followed by 2 s of rest) is PSA(T1) of the record, which the response
    spectrum reads between samples (at most (ω·dt)²/8 = 5e-4 above).
    (a_floor − ü_g)/(γ1·ψ1) + ü_g recovers ü_g + D̈1."""
    acc = np.concatenate([record_factory(5), np.zeros(200)])  # 2 s of free vibration
    gamma_psi = 3 * 4 / (2 * 4 + 1) * 6.0 / 12.0  # γ1 (n = 4) · Z/H_b
    floor = floor_acceleration(
        acc, 0.01, height_building=12.0, storeys=4, wall_base=6.0, period=1.0, damping=0.0
    )
    absolute = (floor - acc) / gamma_psi + acc
    psa = response_spectrum(acc, 0.01, [1.0], damping=0.0)[0]
    assert np.max(np.abs(absolute)) <= psa * (1 + 1e-9)
    assert np.max(np.abs(absolute)) >= psa * (1 - 1e-3)


def test_floor_motion_rejects_impossible_buildings():
    acc = np.zeros(10)
    base = dict(height_building=12.0, storeys=4, wall_base=6.0, period=0.3, damping=0.05)
    for key, bad in [
        ("storeys", 0),
        ("wall_base", 12.5),
        ("wall_base", -1.0),
        ("period", 0.0),
        ("damping", 1.0),
        ("height_building", 0.0),
    ]:
        with pytest.raises(ValueError):
            floor_acceleration(acc, 0.01, **{**base, key: bad})


def test_participation_factor_and_default_period():
    """γ1 = 3n/(2n+1) (eq. C7.2.10); T1 = 0.050·H^(3/4) (Circolare eq. C7.3.2)."""
    assert participation_factor(1) == pytest.approx(1.0)
    assert participation_factor(4) == pytest.approx(12 / 9)
    # 12^0.75 = e^(0.75·ln 12) = e^(0.75·2.484907) = e^1.863680 = 6.447420
    assert default_period(12.0) == pytest.approx(0.05 * 6.447420, rel=1e-6)


def _ground(T, xi):
    """A hand-checkable ground spectrum [g]: 0.6·η up to 0.5 s, then 0.6·η·0.5/T."""
    eta = max(math.sqrt(10 / (5 + 100 * xi)), 0.55)
    T = np.asarray(T, dtype=float)
    return np.where(T <= 0.5, 0.6 * eta, 0.6 * eta * 0.5 / np.maximum(T, 1e-12))


# T1 = 0.4 s, ξ1 = 5 %, n = 3, z/H = 2/3:
#   γ1·ψ1 = 9/7 · 2/3 = 6/7;  Se(T1, ξ1) = 0.6;  √(1 + 0.0004·5²) = √1.01 = 1.004988
#   a_Z = 0.6 · 6/7 · 1.004988 = 0.516851                                   (eq. C7.2.7)
#   A = 1.1 · 0.05^-0.5 · η(5 %) = 1.1 · 4.472136 · 1 = 4.919350            (eq. C7.2.9)
#   plateau A·a_Z = 2.542569;  a·T1 = 0.32 s,  b·T1 = 0.44 s                  (eq. C7.2.6)
A_Z = 0.6 * 6 / 7 * math.sqrt(1.01)
AMP = 1.1 / math.sqrt(0.05)
TOP = AMP * A_Z
FLOOR = dict(period=0.4, storeys=3, z_over_h=2 / 3, building_damping=0.05)


def test_floor_spectrum_values_by_hand():
    """Circolare 2019 eqs. C7.2.5-C7.2.9, first mode, a = 0.8, b = 1.1."""
    assert A_Z == pytest.approx(0.516851, abs=2e-6)
    assert TOP == pytest.approx(2.542569, abs=2e-6)
    periods = [0.0, 0.16, 0.40, 0.88, 2.0]
    expected = [
        A_Z,  # T = 0: A·a_Z/(1 + (A − 1)·1) = a_Z, the floor's peak acceleration
        # T = 0.16: (1 − 0.16/0.32)^1.6 = 0.5^1.6 = 0.329877; 2.542569/(1 + 3.919350·0.329877)
        TOP / (1 + (AMP - 1) * 0.5**1.6),  # = 1.108887
        TOP,  # plateau 0.32 ≤ T < 0.44
        # T = 0.88: (0.88/0.44 − 1)^1.2 = 1 → a_Z = 0.516851 > ground 0.6·0.5/0.88 = 0.340909
        A_Z,
        # T = 2.0: (2/0.44 − 1)^1.2 = 3.545455^1.2 = 4.566892 → 2.542569/18.899246 = 0.134533,
        # below the ground's 0.6·0.5/2 = 0.15, which eq. C7.2.5 keeps for T > T1
        0.15,
    ]
    got = floor_spectrum(periods, _ground, **FLOOR)
    np.testing.assert_allclose(got, expected, rtol=1e-9)
    assert got[1] == pytest.approx(1.108887, abs=2e-6)


def test_floor_spectrum_at_8_percent_element_damping():
    """η(8 %) = √(10/13) = 0.877058 lowers the plateau to 4.919350·0.877058·a_Z = 2.229981."""
    got = floor_spectrum([0.4], _ground, **FLOOR, damping=0.08)[0]
    assert got == pytest.approx(2.229981, abs=2e-6)


def test_floor_displacement_spectrum_by_hand():
    """S_eZ·(T/2π)²·g, not below the plateau's value at b·T1 beyond it (eq. C8.7.1.12)."""
    bound = TOP * G * (0.44 / (2 * math.pi)) ** 2  # 2.542569·9.80665·0.0049039 = 0.122275
    got = floor_displacement_spectrum([0.4, 0.88, 2.0], _ground, **FLOOR)
    expected = [
        TOP * G * (0.4 / (2 * math.pi)) ** 2,  # 0.101053 m on the plateau
        bound,  # 0.516851·g·(0.88/2π)² = 0.099425 m < 0.122275 m
        0.15 * G * (2.0 / (2 * math.pi)) ** 2,  # 0.149044 m > 0.122275 m
    ]
    np.testing.assert_allclose(got, expected, rtol=1e-9)
    assert bound == pytest.approx(0.122275, abs=2e-6)
    assert got[0] == pytest.approx(0.101053, abs=2e-6)


def test_ground_level_uses_the_ground_spectrum():
    """z = 0: the wall is checked on the ground spectrum (§C8.7.1.2.1.8)."""
    periods = [0.0, 0.3, 1.5]
    got = floor_spectrum(periods, _ground, period=0.4, storeys=3, z_over_h=0.0)
    np.testing.assert_allclose(got, _ground(periods, 0.05))
    disp = floor_displacement_spectrum([1.5], _ground, period=0.4, storeys=3, z_over_h=0.0)
    ground = ground_displacement_spectrum([1.5], _ground, 0.05)
    assert disp[0] == pytest.approx(ground[0])
    assert ground[0] == pytest.approx(0.2 * G * (1.5 / (2 * math.pi)) ** 2)


def test_ground_spectrum_function_follows_the_damping():
    """η(ξ) of NTC 2018 eq. 3.2.4 on the EC8 shape: plateau 2.5·a_g·S·η."""
    spectrum = ec8_spectrum(0.25, "B")
    se = ground_spectrum_function(spectrum)
    periods = np.array([0.0, 0.3, 1.0, 3.0])
    np.testing.assert_allclose(se(periods, 0.05), spectrum.sa(periods))
    plateau = se(np.array([0.3]), 0.10)[0]
    assert plateau == pytest.approx(2.5 * spectrum.pga_g * math.sqrt(10 / 15))
