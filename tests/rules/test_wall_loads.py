"""Simple overturning with loads and ties (rules/wall_loads.py, rules/tie_rods.py).

References: Circolare 2019 §C8.7.1.2, eq. C8.7.1.1 (α₀ of the linear kinematic analysis: the
stabilising work of the weights and loads, minus the thrusts', plus the internal work of a
tie, over the work of the horizontal inertia) and eq. C8.7.1.5 (e*).  The expected values are
computed by hand from those formulas for one façade, B = 0.40 m, H = 6.00 m, w = 18 kN/m³,
W = 18 × 0.40 × 6.00 = 43.2 kN/m, and written here as numbers (the arithmetic is in each
comment); the impact ratio is checked against Housner's 1 − 1.5·sin²α and against the angular
momentum of the block summed point by point (an independent discretisation).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frp_assess.rules.tie_rods import (
    round_bar_area,
    tie_anchorage_force,
    tie_capacity,
    tie_elongation,
    tie_force,
    tie_is_ductile,
    tie_stiffness,
    tie_yield_force,
)
from frp_assess.rules.wall_loads import (
    Thrust,
    TopLoad,
    impact_velocity_ratio,
    multiplier_at_rotation,
    overturning_multiplier,
    participating_mass_ratio,
    uplift_multiplier,
)

B, H, W = 0.40, 6.00, 43.2e3  # m, m, N/m
FLOOR = TopLoad(10e3, 0.30, True)  # 10 kN/m bearing 0.30 m from the outer face, carried


def test_a_floor_hand_calculation() -> None:
    """α₀ = (43.2·0.20 + 10·0.30)/(43.2·3 + 10·6) = 11.64/189.6 = 0.0613924;
    e* = 189.6²/(53.2·(43.2·36/4 + 10·36)) = 35 948.16/39 836.16 = 0.9024002."""
    assert overturning_multiplier(W, B, H, [FLOOR], []) == pytest.approx(0.0613924051, rel=1e-9)
    assert uplift_multiplier(W, B, H, [FLOOR], [], 1) == pytest.approx(0.0613924051, rel=1e-9)
    assert participating_mass_ratio(W, H, [FLOOR]) == pytest.approx(0.9024002313, rel=1e-9)


def test_the_issue_example_a_floor_as_heavy_as_the_wall_at_mid_thickness() -> None:
    """Issue 40: (W·B/2 + W·B/2)/(W·H/2 + W·H) = ⅔·B/H."""
    floor = TopLoad(W, B / 2, True)
    assert overturning_multiplier(W, B, H, [floor], []) == pytest.approx(2 / 3 * B / H)


def test_a_floor_and_a_thrust_hand_calculation() -> None:
    """A thrust of 2 kN/m at 5.5 m: outward α₀ = (11.64 − 2·5.5)/189.6 = 0.64/189.6 =
    0.00337553; inward a_RM,−/g = (8.64 + 10·0.10 + 11.0)/189.6 = 20.64/189.6 = 0.1088608."""
    thrust = Thrust(2e3, 5.5)
    assert overturning_multiplier(W, B, H, [FLOOR], [thrust]) == pytest.approx(
        0.0033755274, rel=1e-8
    )
    assert uplift_multiplier(W, B, H, [FLOOR], [thrust], -1) == pytest.approx(
        0.1088607595, rel=1e-9
    )


def test_a_floor_and_a_tie_hand_calculation() -> None:
    """A Ø20 S235 tie every 3.0 m at 5.8 m: A_s = π·20²/4 = 314.159 mm², F_y = 314.159e-6 ×
    235e6/3 = 24 609.14 N/m, L_i = 24.60914 × 5.8 = 142.7330 kN·m/m, α₀ = (11.64 + 142.7330)/
    189.6 = 0.8142037.  With an anchorage of 30 kN per tie, 10 kN/m < F_y governs: α₀ =
    (11.64 + 10 × 5.8)/189.6 = 0.3672996."""
    area = round_bar_area(0.020)
    assert area == pytest.approx(314.159265e-6, rel=1e-8)
    f_y = tie_yield_force(area, 235e6, 3.0)
    assert f_y == pytest.approx(24609.142, rel=1e-7)
    steel = tie_capacity(f_y, tie_anchorage_force(None, 3.0))
    assert overturning_multiplier(W, B, H, [FLOOR], [], steel * 5.8) == pytest.approx(
        0.8142037248, rel=1e-9
    )
    plate = tie_anchorage_force(30e3, 3.0)
    assert plate == pytest.approx(10e3)
    assert not tie_is_ductile(f_y, plate) and tie_is_ductile(f_y, math.inf)
    held = tie_capacity(f_y, plate) * 5.8
    assert overturning_multiplier(W, B, H, [FLOOR], [], held) == pytest.approx(
        0.3672995781, rel=1e-9
    )


def test_no_load_is_the_free_standing_wall() -> None:
    """Without loads: α₀ = tan α = B/H, e* = 1, and the capacity curve is
    (tan α·cos θ − sin θ)/(cos θ + tan α·sin θ) = tan(α − θ) (Circolare C8.7.1.2.1)."""
    assert overturning_multiplier(W, B, H, [], []) == pytest.approx(B / H)
    assert uplift_multiplier(W, B, H, [], [], -1) == pytest.approx(B / H)
    assert participating_mass_ratio(W, H, []) == pytest.approx(1.0)
    alpha = math.atan(B / H)
    for theta in (0.0, 0.01, 0.05):
        assert multiplier_at_rotation(theta, W, B, H, [], []) == pytest.approx(
            math.tan(alpha - theta)
        )


def test_a_restrained_load_holds_but_brings_no_inertia() -> None:
    """A restrained floor: (8.64 + 3.0)/129.6 = 0.0898148; e* of the wall alone, 1."""
    held = TopLoad(10e3, 0.30, False)
    assert overturning_multiplier(W, B, H, [held], []) == pytest.approx(0.0898148148, rel=1e-9)
    assert participating_mass_ratio(W, H, [held]) == pytest.approx(1.0)


def test_capacity_curve_with_a_floor_vanishes_where_the_moments_balance() -> None:
    """At θ where W·(B/2·cosθ − H/2·sinθ) + P·(d·cosθ − H·sinθ) = 0, i.e. tan θ =
    (W·B/2 + P·d)/(W·H/2 + P·H) = α₀ (hand: the same ratio), α(θ) = 0."""
    theta = math.atan(0.0613924051)
    assert multiplier_at_rotation(theta, W, B, H, [FLOOR], []) == pytest.approx(0.0, abs=1e-9)


def test_impact_ratio_reduces_to_housner() -> None:
    """Housner (1963): 1 − 1.5·sin²α for a rectangular block."""
    m = W / 9.80665
    alpha = math.atan(B / H)
    for side in (1, -1):
        assert impact_velocity_ratio(m, B, H, [], side) == pytest.approx(
            1 - 1.5 * math.sin(alpha) ** 2
        )


@pytest.mark.parametrize("new_side", [1, -1])
def test_impact_ratio_with_a_top_mass_against_a_point_by_point_sum(new_side: int) -> None:
    """The angular momentum about the new corner before the impact, Σ m·(r_old · r_new)·ω,
    over the new inertia Σ m·|r_new|², summed over a 400 × 400 grid of the block plus the top
    mass: an independent discretisation of the same conservation law."""
    m = W / 9.80665
    m_top, d_top = 10e3 / 9.80665, 0.30
    n = 400
    xs = (np.arange(n) + 0.5) / n * B  # from the outer face
    ys = (np.arange(n) + 0.5) / n * H
    x, y = np.meshgrid(xs, ys)
    dm = m / (n * n)
    # the old pivot is the other corner: outer (x = 0) when the new one is inner (x = B)
    old_x, new_x = (B, 0.0) if new_side > 0 else (0.0, B)
    before = dm * np.sum((x - old_x) * (x - new_x) + y * y)
    before += m_top * ((d_top - old_x) * (d_top - new_x) + H * H)
    inertia = dm * np.sum((x - new_x) ** 2 + y * y) + m_top * ((d_top - new_x) ** 2 + H * H)
    got = impact_velocity_ratio(m, B, H, [(m_top, d_top)], new_side)
    assert got == pytest.approx(before / inertia, rel=1e-5)


def test_tie_is_elastic_perfectly_plastic_in_tension_only() -> None:
    """F_t = clip(k_t·(δ − δ_p), 0, F_y): slack for θ ≤ 0, capped at F_y, and the plastic
    elongation shifts the unloading branch (EN 1993-1-1 idealisation of the steel)."""
    k = tie_stiffness(round_bar_area(0.020), 210e9, 8.0, 3.0)  # 210e9·314.16e-6/24 = 2.7489e6 N/m/m
    assert k == pytest.approx(2.74889e6, rel=1e-5)
    f_y = tie_yield_force(round_bar_area(0.020), 235e6, 3.0)
    assert tie_elongation(5.8, -0.01) == 0.0
    assert tie_force(k, f_y, tie_elongation(5.8, -0.01), 0.0) == 0.0
    small = tie_elongation(5.8, 1e-4)
    assert tie_force(k, f_y, small, 0.0) == pytest.approx(k * 5.8 * math.sin(1e-4))
    assert tie_force(k, f_y, 0.1, 0.0) == f_y
    # after yielding to δ = 0.1 the plastic elongation is 0.1 − F_y/k; back at δ = 0.05 slack
    delta_p = 0.1 - f_y / k
    assert tie_force(k, f_y, 0.05, delta_p) == 0.0
    assert tie_force(k, f_y, delta_p + 0.001, delta_p) == pytest.approx(k * 0.001)
