"""The codes' spectrum coefficients against their tables, typed here from the documents:
NTC 2018 Tab. 3.2.IV (S_S = a − b·F0·a_g/g within [lo, hi], C_C = c·(T_C*)^e), Tab. 3.2.V
(S_T), Eqs. 3.2.5–3.2.7 (T_B = T_C/3, T_C = C_C·T_C*, T_D = 4·a_g/g + 1.6); EN 1998-1
Eq. 3.6 (η = √(10/(5 + ξ)) ≥ 0.55) and Tables 3.2/3.3."""

from __future__ import annotations

import math

import pytest

from frp_assess.rules.spectrum import EC8_TABLE, c_c, eta, s_s, s_t, t_b, t_c, t_d

#: NTC 2018 Tab. 3.2.IV: soil -> (a, b, lo, hi) of S_S, (c, e) of C_C
TAB_3_2_IV = {
    "A": ((1.00, 0.00, 1.00, 1.00), (1.00, 0.00)),
    "B": ((1.40, 0.40, 1.00, 1.20), (1.10, -0.20)),
    "C": ((1.70, 0.60, 1.00, 1.50), (1.05, -0.33)),
    "D": ((2.40, 1.50, 0.90, 1.80), (1.25, -0.50)),
    "E": ((2.00, 1.10, 1.00, 1.60), (1.15, -0.40)),
}
#: EN 1998-1 Table 3.2 (type 1), Table 3.3 (type 2): ground -> (S, T_B, T_C, T_D)
EC8 = {
    1: {"A": (1.00, 0.15, 0.40, 2.0), "B": (1.20, 0.15, 0.50, 2.0), "C": (1.15, 0.20, 0.60, 2.0),
        "D": (1.35, 0.20, 0.80, 2.0), "E": (1.40, 0.15, 0.50, 2.0)},
    2: {"A": (1.00, 0.05, 0.25, 1.2), "B": (1.35, 0.05, 0.25, 1.2), "C": (1.50, 0.10, 0.25, 1.2),
        "D": (1.80, 0.10, 0.30, 1.2), "E": (1.60, 0.05, 0.25, 1.2)},
}  # fmt: skip


@pytest.mark.parametrize("soil", sorted(TAB_3_2_IV))
@pytest.mark.parametrize("ag,f0", [(0.05, 2.4), (0.25, 2.5), (0.40, 2.6)])
def test_s_s_by_hand(soil: str, ag: float, f0: float) -> None:
    (a, b, lo, hi), _ = TAB_3_2_IV[soil]
    assert s_s(soil, ag, f0) == pytest.approx(min(max(a - b * f0 * ag, lo), hi), rel=1e-15)


@pytest.mark.parametrize("soil", sorted(TAB_3_2_IV))
def test_c_c_and_the_corner_periods_by_hand(soil: str) -> None:
    _, (c, e) = TAB_3_2_IV[soil]
    assert c_c(soil, 0.3) == pytest.approx(c * 0.3**e, rel=1e-15)
    assert t_c(c_c(soil, 0.3), 0.3) == pytest.approx(c * 0.3**e * 0.3, rel=1e-15)
    assert t_b(0.6) == pytest.approx(0.2)


def test_s_s_of_soil_b_at_a_strong_site() -> None:
    """Soil B, a_g = 0.25 g, F0 = 2.5: 1.40 − 0.40·2.5·0.25 = 1.15 (within [1.00, 1.20])."""
    assert s_s("B", 0.25, 2.5) == pytest.approx(1.15)


@pytest.mark.parametrize("category,value", [("T1", 1.0), ("T2", 1.2), ("T3", 1.2), ("T4", 1.4)])
def test_s_t_is_tab_3_2_v(category: str, value: float) -> None:
    assert s_t(category) == value


def test_t_d_and_eta_by_hand() -> None:
    assert t_d(0.25) == pytest.approx(2.6)
    assert eta(0.05) == 1.0
    assert eta(0.10) == pytest.approx(math.sqrt(10 / 15))
    assert eta(0.50) == 0.55  # the floor of Eq. 3.6


def test_ec8_tables() -> None:
    assert EC8_TABLE == EC8


def test_an_unknown_soil_is_a_key_error() -> None:
    with pytest.raises(KeyError):
        s_s("F", 0.1, 2.5)
