"""The masonry rules against hand calculations (SI units).

Sources: Circolare 2019 Tab. C8.5.IV (FC 1.35 / 1.20 / 1.00 for LC1 / LC2 / LC3) and §C8.7.1
(f_d = f_m/FC); NTC 2018 §7.8.2.2.1 (stress block 0.85·f_d); docs/model.md §1.1 (N = W + T,
x = N/(0.85·f_d·1 m), the refusal x_W ≥ B).
"""

from __future__ import annotations

import math

import pytest

from frp_assess.rules.masonry import (
    CONFIDENCE_FACTORS,
    STRESS_BLOCK_FACTOR,
    base_carries_weight,
    base_force,
    compressed_zone_depth,
    confidence_factor,
    crushing_depth,
    design_strength,
    force_for_depth,
    toe_crushes,
    wall_weight,
    weight_not_carried,
)


def test_confidence_factors_of_the_circolare() -> None:
    assert [confidence_factor(lc) for lc in ("LC1", "LC2", "LC3")] == [1.35, 1.20, 1.00]
    assert list(CONFIDENCE_FACTORS) == ["LC1", "LC2", "LC3"]
    with pytest.raises(KeyError):
        confidence_factor("LC4")


def test_design_strength() -> None:
    # solid brick at LC1: f_m = 2.6 MPa, f_d = 2.6/1.35 = 1.9259 MPa; with γ_M = 2: 0.96296
    assert design_strength(2.6e6, 1.35) == pytest.approx(1.925926e6, rel=1e-6)
    assert design_strength(2.6e6, 1.35, 2.0) == pytest.approx(0.962963e6, rel=1e-6)


def test_weight_force_and_depth_by_hand() -> None:
    # B = 0.25 m, H = 3 m, w = 18 kN/m³: W = 13.5 kN/m; a bar pulling 731.25 kN/m: N = 744.75
    weight = wall_weight(18e3, 0.25, 3.0)
    assert weight == pytest.approx(13.5e3)
    n = base_force(weight, 731.25e3)
    assert n == pytest.approx(744.75e3)
    assert base_force(weight) == weight
    # f_d = 2.6/1.35 MPa: 0.85·f_d = 1.637037 MPa, x = 744.75e3/1.637037e6 = 0.454938 m
    f_d = 2.6e6 / 1.35
    assert STRESS_BLOCK_FACTOR == 0.85
    assert compressed_zone_depth(n, f_d) == pytest.approx(0.454938, abs=1e-6)
    assert compressed_zone_depth(n, math.inf) == 0.0  # the paper's edge pivot


def test_force_for_depth_is_the_inverse_of_the_depth() -> None:
    # 0.85 · 2.875 MPa over 0.1 m carries 244.375 kN/m
    assert force_for_depth(0.1, 2.875e6) == pytest.approx(244.375e3)
    for n in (1e3, 21.6e3, 159.6e3):
        assert force_for_depth(compressed_zone_depth(n, 2.875e6), 2.875e6) == pytest.approx(n)


def test_the_base_carries_the_weight_while_x_w_is_below_b() -> None:
    # w·H against 0.85·f_d: f_d = 0.1/1.35 MPa, 0.85·f_d = 62.963 kPa; H = 3.4 m: 61.2 kPa
    # carried (x_W = 0.972·B); H = 4 m: 72 kPa not carried (x_W = 1.144·B)
    f_d = 0.1e6 / 1.35
    assert base_carries_weight(wall_weight(18e3, 0.3, 3.4), 0.3, f_d)
    assert not base_carries_weight(wall_weight(18e3, 0.3, 4.0), 0.3, f_d)
    assert base_carries_weight(wall_weight(18e3, 0.3, 40.0), 0.3, math.inf)
    line = weight_not_carried(wall_weight(18e3, 0.3, 4.0), 0.3, f_d)
    assert "\n" not in line and "x = W/(0.85*f_d) = 343 mm" in line and "B = 300 mm" in line


def test_the_toe_crushes_at_the_bar_or_at_b() -> None:
    """docs/model.md §1.1: the toe crushes when x reaches the acting bar's distance from the
    corner (B/2 centred, B external) or B; B = 0.4 m."""
    assert crushing_depth(0.4) == 0.4
    assert crushing_depth(0.4, 0.2) == 0.2  # centred bar
    assert crushing_depth(0.4, 0.4) == 0.4  # external bar
    assert not toe_crushes(0.19, 0.4, 0.2) and toe_crushes(0.2, 0.4, 0.2)
    assert not toe_crushes(0.39, 0.4, 0.4) and toe_crushes(0.4, 0.4)
