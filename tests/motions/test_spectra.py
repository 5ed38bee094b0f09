"""Code spectra against the test vectors of issue 3, computed by hand from the clauses.

Sources: EN 1998-1:2004 §3.2.2.2 (Eqs. 3.2–3.5, Tables 3.2/3.3); NTC 2018 §3.2.3.2.1
(Eqs. 3.2.2–3.2.6, Tab. 3.2.IV–V).
"""

from __future__ import annotations

import pytest

from frp_assess.motions.spectra import (
    EC8_TABLE,
    ec8_spectrum,
    eta,
    ntc2018_spectrum,
    preset_spectrum,
    table_spectrum,
)


def test_ec8_type1_ground_b_vector():
    sp = ec8_spectrum(0.25, "B", 1)
    assert sp.pga_g == pytest.approx(0.300)
    assert sp.sa([0.0])[0] == pytest.approx(0.300)
    assert sp.sa([0.3])[0] == pytest.approx(0.750)
    assert sp.sa([1.0])[0] == pytest.approx(0.375)
    assert sp.sa([3.0])[0] == pytest.approx(0.08333, abs=1e-5)


@pytest.mark.parametrize("stype", [1, 2])
@pytest.mark.parametrize("ground", list("ABCDE"))
def test_ec8_corners_from_tables(stype, ground):
    S, tb, tc, td = EC8_TABLE[stype][ground]
    sp = ec8_spectrum(0.2, ground, stype)
    assert sp.sa([tb, tc])[0] == pytest.approx(0.2 * S * 2.5)
    assert sp.sa([tc])[0] == pytest.approx(0.2 * S * 2.5)
    assert sp.sa([td])[0] == pytest.approx(0.2 * S * 2.5 * tc / td)
    # continuity at the corners
    for t in (tb, tc, td):
        lo, hi = sp.sa([t * (1 - 1e-9), t * (1 + 1e-9)])
        assert lo == pytest.approx(hi, rel=1e-6)


def test_eta():
    assert eta(0.05) == 1.0
    assert eta(0.10) == pytest.approx((10 / 15) ** 0.5)
    assert eta(0.50) == 0.55  # floor


def test_ntc_vector():
    sp = ntc2018_spectrum(0.25, 2.4, 0.30, "C", "T1")
    assert sp.parameters["S_S"] == pytest.approx(1.34)
    assert sp.T_C == pytest.approx(0.4687, abs=1e-4)
    assert sp.T_B == pytest.approx(sp.T_C / 3)
    assert sp.T_D == pytest.approx(2.60)
    assert sp.sa([0.3])[0] == pytest.approx(0.804)
    assert sp.sa([1.0])[0] == pytest.approx(0.3768, abs=1e-4)
    assert sp.pga_g == pytest.approx(0.25 * 1.34)


@pytest.mark.parametrize(
    "soil,lo,hi", [("B", 1.0, 1.2), ("C", 1.0, 1.5), ("D", 0.9, 1.8), ("E", 1.0, 1.6)]
)
def test_ntc_ss_bounds(soil, lo, hi):
    assert ntc2018_spectrum(0.01, 2.5, 0.3, soil).parameters["S_S"] == pytest.approx(hi)
    assert ntc2018_spectrum(1.0, 3.0, 0.3, soil).parameters["S_S"] == pytest.approx(lo)


def test_topography_multiplies():
    t1 = ntc2018_spectrum(0.2, 2.4, 0.3, "B", "T1")
    t4 = ntc2018_spectrum(0.2, 2.4, 0.3, "B", "T4")
    assert t4.pga_g == pytest.approx(1.4 * t1.pga_g)


def test_presets_and_table():
    a2 = preset_spectrum("A2")
    assert a2.pga_g == 0.106 and a2.sa([0.3])[0] == pytest.approx(0.265)
    with pytest.raises(ValueError):
        preset_spectrum("A9")
    tab = table_spectrum([0.0, 0.5, 1.0], [0.2, 0.5, 0.25])
    assert tab.sa([0.25, 2.0]) == pytest.approx([0.35, 0.25])
