"""Displacement-based kinematic check (frp_assess.assess.kinematic_nonlinear).

Worked examples computed here from the clauses of Circolare 2019 §C8.7.1.2.1 and the
geometry of docs/model.md (the paper's wall: H = 3 m, α = 7.5°, w = 18 kN/m³), not read
back from the module.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frp_assess.assess.kinematic_capacity import (
    capacity_curve,
    control_displacement,
    participating_mass,
    participating_mass_fraction,
    spectral_acceleration,
    spectral_displacement,
    static_multiplier,
)
from frp_assess.assess.kinematic_nonlinear import (
    a_g_limit,
    a_g_sld,
    d_slc,
    d_slv,
    displacement_demand,
    limit_state_check,
    t_slc,
    t_slv,
    time_history_check,
    zeta_e,
)
from frp_assess.dynamics import Rebars, Wall

G = 9.80665
ALPHA = math.radians(7.5)
WALL = Wall.from_slenderness(3.0, ALPHA, 18e3)
# B = 3·tan 7.5° = 0.394958 m; R = ½·√(B² + 3²) = 1.512943 m; m = w·B·H/g = 2174.82 kg/m
B = 3.0 * math.tan(ALPHA)
R = 0.5 * math.hypot(B, 3.0)
FC = 1.35


def _theta_at(d):
    """Rotation at which the centroid has moved d: R·[sin α − sin(α − θ)] = d."""
    return ALPHA - math.asin(math.sin(ALPHA) - d / R)


def _k(elastic_modulus, position, ratio=1.0):
    """K = sin α·tan α·(r_p/2)·E·ρ/(w·H) of Eq. 10 (docs/model.md §3.1)."""
    r_p = 1.0 if position == "centred" else 4.0
    return math.sin(ALPHA) * math.tan(ALPHA) * r_p / 2 * elastic_modulus * ratio * 1e-3 / (18e3 * 3)


def test_static_multiplier_is_the_equilibrium_of_eq_10():
    """θ'' = 0 in Eq. 10 with ü_g = −α·g: sin(α_w − θ) − α·cos(α_w − θ) + K·sin θ = 0.
    α(0) = tan α_w = B/H with or without bars (eq. C8.7.1.1, bars unstressed at rest);
    without bars α(α_w) = 0."""
    assert static_multiplier(0.0, ALPHA) == pytest.approx(B / 3.0)
    assert static_multiplier(0.0, ALPHA, 7.32) == pytest.approx(B / 3.0)
    assert static_multiplier(ALPHA, ALPHA) == pytest.approx(0.0, abs=1e-15)
    theta = np.linspace(0.0, 0.12, 7)
    mult = static_multiplier(theta, ALPHA, 7.32)
    residual = np.sin(ALPHA - theta) - mult * np.cos(ALPHA - theta) + 7.32 * np.sin(theta)
    np.testing.assert_allclose(residual, 0.0, atol=1e-14)
    # θ = 0.05 rad, K = 0: tan(0.130900 − 0.05) = tan 0.080900 = 0.081077
    assert static_multiplier(0.05, ALPHA) == pytest.approx(0.081077, abs=1e-6)


def test_control_displacement_of_the_centroid():
    """d_C = R·[sin α − sin(α − θ)]: B/2 at θ = α; a fallen wall (θ = ∞) is infinitely far."""
    assert control_displacement(ALPHA, WALL) == pytest.approx(B / 2)
    assert control_displacement(ALPHA, WALL) == pytest.approx(0.197479, abs=1e-6)
    assert control_displacement(math.inf, WALL) == math.inf
    got = control_displacement(np.array([0.0, 0.05, np.inf]), WALL)
    assert got[0] == 0.0 and got[2] == math.inf
    assert got[1] == pytest.approx(R * (math.sin(ALPHA) - math.sin(ALPHA - 0.05)))


def test_e_star_m_star_and_d_of_two_blocks():
    """eqs. C8.7.1.3-C8.7.1.5 on two blocks: P = 10 kN, 5 kN; δ = 1, 2; C on block 2 (δ_C = 2).

    Σ P·δ = 10 + 10 = 20 kN, Σ P·δ² = 10 + 20 = 30 kN, Σ P = 15 kN
    e* = 20²/(15·30) = 0.888889;  M* = 20000²/(9.80665·30000) = 4e8/294199.5 = 1359.622 kg
    d = d_C·30/(2·20) = 0.75·d_C;  a = α·g/(e*·FC) = 0.1·9.80665/(0.888889·1.35) = 0.817221
    """
    weights, dx = [10e3, 5e3], [1.0, 2.0]
    assert participating_mass_fraction(weights, dx) == pytest.approx(0.888889, abs=1e-6)
    assert participating_mass(weights, dx) == pytest.approx(1359.622, abs=1e-3)
    assert spectral_displacement(0.1, weights, dx, 2.0) == pytest.approx(0.075)
    assert spectral_acceleration(0.1, 400 / 450, FC) == pytest.approx(0.817221, abs=1e-6)


def test_single_wall_has_e_star_one_and_m_star_its_mass():
    """One block, its weight at the centroid: e* = 1, M* = m = 18e3·B·3/g = 2174.82 kg/m."""
    curve = capacity_curve(WALL, fc=FC)
    assert curve.e_star == pytest.approx(1.0)
    assert curve.m_star == pytest.approx(18e3 * B * 3.0 / G)
    assert curve.m_star == pytest.approx(2174.82, abs=0.01)
    # a0* = tan α·g/FC = 0.131652·9.80665/1.35 = 0.956348 m/s²
    assert curve.a0 == pytest.approx(0.956348, abs=1e-6)
    assert curve.a[0] == pytest.approx(curve.a0)


def test_unreinforced_wall_d0_d_slv_t_slv_t_slc():
    """§C8.7.1.2.1.6 and eqs. C8.7.1.10-11 on the bare wall.

    d0 = B/2 = 0.197479 m;  d_SLV = 0.4·d0 = 0.078991 m;  d_SLC = 0.6·d0 = 0.118487 m
    at d_SLV: sin(α − θ) = 0.130526 − 0.078991/1.512943 = 0.078316, α − θ = 0.078396 rad,
      a = tan(0.078396)·g/1.35 = 0.078557·7.264185 = 0.570653 m/s²
      T_SLV = 1.68·π·√(0.078991/0.570653) = 1.68·π·0.372053 = 1.963647 s
    at d_SLC: a = tan(α − θ)·g/FC with sin(α − θ) = 0.130526 − 0.118487/1.512943 = 0.052210
    """
    curve = capacity_curve(WALL, fc=FC)
    d0 = B / 2
    assert curve.d0 == pytest.approx(d0)
    assert curve.rupture_limit == math.inf
    assert d_slv(curve.d0, curve.rupture_limit) == pytest.approx(0.4 * d0)
    assert d_slc(curve.d0) == pytest.approx(0.6 * d0)
    a_slv = math.tan(ALPHA - _theta_at(0.4 * d0)) * G / FC
    assert a_slv == pytest.approx(0.570653, abs=2e-6)
    assert curve.a_at(0.4 * d0) == pytest.approx(a_slv, rel=1e-12)
    assert t_slv(0.4 * d0, a_slv) == pytest.approx(1.68 * math.pi * math.sqrt(0.4 * d0 / a_slv))
    assert t_slv(0.4 * d0, a_slv) == pytest.approx(1.963647, abs=5e-6)
    a_slc = math.tan(ALPHA - _theta_at(0.6 * d0)) * G / FC
    assert curve.a_at(0.6 * d0) == pytest.approx(a_slc, rel=1e-12)
    assert t_slc(0.6 * d0, a_slc) == pytest.approx(1.56 * math.pi * math.sqrt(0.6 * d0 / a_slc))
    # the sampled curve runs from a0* down to 0 at d0
    assert curve.d[-1] == pytest.approx(d0) and curve.a[-1] == pytest.approx(0.0, abs=1e-12)


def test_centred_gfrp_bars_raise_the_curve_but_not_d0():
    """GFRP centred, ρ = 1 ‰: K = 7.32; θ_max = 2·asin(0.0075·3/0.394957) = 0.113998 rad
    > θ(0.4·d0), so d_SLV = 0.4·d0 with the bar intact:
    α(d_SLV) = [sin(α − θ) + K·sin θ]/cos(α − θ), θ = 0.130900 − 0.078396 = 0.052504 rad."""
    k = _k(46e9, "centred")
    assert k == pytest.approx(7.32, abs=0.005)
    bars = Rebars(46e9, 0.015, "centred", 1.0)
    curve = capacity_curve(WALL, bars, fc=FC)
    assert curve.d0 == pytest.approx(B / 2)  # the bare wall's: brittle bars do not last
    d_lim = d_slv(curve.d0, curve.rupture_limit)
    assert d_lim == pytest.approx(0.4 * B / 2)
    theta = _theta_at(d_lim)
    a_lim = (math.sin(ALPHA - theta) + k * math.sin(theta)) / math.cos(ALPHA - theta) * G / FC
    assert curve.a_at(d_lim) == pytest.approx(a_lim, rel=1e-9)
    assert curve.a_at(d_lim) > 5 * capacity_curve(WALL, fc=FC).a_at(d_lim)


def test_external_cfrp_rupture_limits_d_slv():
    """CFRP external, ρ = 1 ‰: θ_max = 2·asin(0.0065·3/(2·0.394957)) = 0.049377 rad (0.38·α).

    d at rupture = R·[sin α − sin(α − θ_max)] = 1.512943·(0.130526 − 0.081432) = 0.074277 m
    < 0.4·d0 = 0.078991 m.  Before: α = [sin 0.081522 + 95.47·sin 0.049377]/cos 0.081522
    = 4.809; after: tan 0.081522 = 0.081703, far below half of it: d_SLV = 0.074277 m.
    """
    bars = Rebars(150e9, 0.013, "external", 1.0)
    curve = capacity_curve(WALL, bars, fc=FC)
    theta_max = 2 * math.asin(0.5 * 0.013 * 3.0 / (2 * B))  # b_r = B external
    d_rupture = R * (math.sin(ALPHA) - math.sin(ALPHA - theta_max))
    assert d_rupture == pytest.approx(0.074277, abs=2e-6)
    assert curve.rupture_limit == pytest.approx(d_rupture, rel=1e-12)
    assert d_slv(curve.d0, curve.rupture_limit) == pytest.approx(d_rupture, rel=1e-12)
    k = _k(150e9, "external")
    before = (math.sin(ALPHA - theta_max) + k * math.sin(theta_max)) / math.cos(ALPHA - theta_max)
    assert before == pytest.approx(4.809, abs=2e-3)
    assert curve.a_at(d_rupture) == pytest.approx(before * G / FC, rel=1e-9)
    assert curve.a_max == pytest.approx(before * G / FC, rel=1e-9)
    # SLC ignores the rupture (§C8.7.1.2.1.6 gives no rupture criterion for it)
    assert d_slc(curve.d0) == pytest.approx(0.6 * B / 2)


def test_small_drop_at_rupture_does_not_limit_d_slv():
    """A bar whose rupture leaves more than half of the peak capacity: no limit.  Ratio
    0.05 ‰ of CFRP external (K = 4.77): at θ_max the curve falls from
    [0.081432 + 4.77·0.049357]/0.996679 = 0.3181 to 0.0817, i.e. below half: limit; a bar
    that breaks at 0.02 rad with K = 0.2 falls from [sin 0.1109 + 0.2·sin 0.02]/cos 0.1109 =
    0.1154 to tan 0.1109 = 0.1114, more than half of the peak α0 = 0.1317: no limit."""
    limited = capacity_curve(WALL, Rebars(150e9, 0.013, "external", 0.05), fc=FC)
    assert math.isfinite(limited.rupture_limit)
    # K = 0.2 with θ_max = 0.02: a centred bar of E chosen for K and ε for θ_max
    e_for_k = 0.2 / _k(1.0, "centred")  # K is linear in E
    eps_for_theta = 2 * math.sin(0.01) * (B / 2) / 3.0 / 0.5  # θ_max = 2·asin(c·ε·H/(2·b_r))
    gentle = capacity_curve(WALL, Rebars(e_for_k, eps_for_theta, "centred", 1.0), fc=FC)
    assert gentle.rupture_rotation == pytest.approx(0.02)
    assert gentle.stiffness == pytest.approx(0.2)
    assert gentle.rupture_limit == math.inf


def test_displacement_demand_is_the_largest_value_up_to_the_period():
    """§C8.7.1.2.1.8: Sd at T_s for a growing spectrum; the largest value in [T0, T_s] for a
    record's spectrum with a peak (here 0.09 m at 0.5 s, 0.06 m beyond 1 s)."""

    def growing(T, xi):
        return 0.05 * math.sqrt(10 / (5 + 100 * xi)) * T  # η(8 %) = 0.877058

    assert displacement_demand(growing, 1.5, 0.08) == pytest.approx(0.05 * 0.877058 * 1.5, 1e-6)

    def peaked(T, xi):
        return 0.09 * T / 0.5 if T <= 0.5 else max(0.06, 0.09 - 0.06 * (T - 0.5))

    assert displacement_demand(peaked, 2.0, 0.08) == pytest.approx(0.09, rel=1e-6)
    assert displacement_demand(peaked, 0.25, 0.08) == pytest.approx(0.045)


def test_a_g_limit_scales_the_intensity_and_keeps_a_g_sld():
    """a_g,SLV = a_g·d_SLV/D (demand ∝ a_g), not below a_g,SLD (below eq. C8.7.1.12);
    ζ_E = a_g,SLV/a_g; a_g,SLD = a0*/(a_Z/a_g) (eq. C8.7.1.8)."""
    assert a_g_limit(0.3, 0.079, 0.0862) == pytest.approx(0.3 * 0.079 / 0.0862)
    assert a_g_limit(0.3, 0.02, 0.10, a_g_sld_value=0.1) == pytest.approx(0.1)
    assert zeta_e(0.275, 0.3) == pytest.approx(0.916667, abs=1e-6)
    assert a_g_sld(0.956348, 2.0) == pytest.approx(0.478174)


def test_limit_state_check_on_the_bare_wall():
    """SLV with Sd(T, ξ) = 0.05·η(ξ)·T [m] at a_g = 0.3 g: D = 0.05·0.877058·1.963647 =
    0.086112 m > d_SLV = 0.078991 m, so a_g,SLV = 0.3·0.078991/0.086112 = 0.275195 g and the
    check fails (ζ_E = 0.917)."""
    curve = capacity_curve(WALL, fc=FC)

    def sd(T, xi):
        return 0.05 * math.sqrt(10 / (5 + 100 * xi)) * T

    slv = limit_state_check(curve, "SLV", sd, 0.3)
    assert slv.damping == 0.08 and slv.period == pytest.approx(1.963647, abs=5e-6)
    assert slv.demand == pytest.approx(0.05 * math.sqrt(10 / 13) * slv.period)
    assert slv.a_g_capacity == pytest.approx(0.275195, abs=2e-6)
    assert slv.zeta_e == pytest.approx(0.275195 / 0.3, abs=1e-5)
    assert not slv.passed
    slc = limit_state_check(curve, "SLC", sd, 0.3)
    assert slc.damping == 0.10 and slc.d_limit == pytest.approx(0.6 * B / 2)
    assert slc.demand == pytest.approx(0.05 * math.sqrt(10 / 15) * slc.period)


def test_time_history_check():
    """§C8.7.1.2.1.9: no peak above d0 and mean of the peaks ≤ d_SLV."""
    d0, d_lim = 0.1975, 0.0790
    ok = time_history_check([0.02, 0.05, 0.08], d0, d_lim)  # mean 0.05
    assert ok.passed and ok.mean_peak == pytest.approx(0.05) and ok.max_peak == 0.08
    assert ok.ratio == pytest.approx(0.0790 / 0.05)
    high_mean = time_history_check([0.07, 0.09, 0.10], d0, d_lim)  # mean 0.0867 > 0.079
    assert high_mean.d0_respected and not high_mean.mean_respected and not high_mean.passed
    one_over_d0 = time_history_check([0.01, 0.01, 0.20], d0, d_lim)  # mean 0.0733, 0.20 > d0
    assert one_over_d0.mean_respected and not one_over_d0.d0_respected
    assert not one_over_d0.passed
    fell = time_history_check([0.01, math.inf], d0, d_lim)
    assert not fell.passed and fell.ratio == 0.0
    # the margin that decides: min(d_lim/mean, d0/largest), by hand
    assert ok.margin == pytest.approx(min(0.0790 / 0.05, 0.1975 / 0.08))  # 1.58, d_lim governs
    assert high_mean.margin == pytest.approx(0.0790 / (0.26 / 3))  # 0.912
    assert one_over_d0.ratio > 1.0  # d_lim/mean alone would pass it
    assert one_over_d0.margin == pytest.approx(0.1975 / 0.20)  # 0.9875 < 1: d0 governs
    assert fell.margin == 0.0
    assert time_history_check([0.0, 0.0], d0, d_lim).margin is None  # nothing rocked
    with pytest.raises(ValueError):
        time_history_check([], d0, d_lim)
