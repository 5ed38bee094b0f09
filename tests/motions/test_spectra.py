"""Elastic spectra (frp_assess.motions.spectra): EN 1998-1 §3.2.2.2, NTC 2018 §3.2.3.2.1,
user tables, the paper's presets (docs/model.md §6) and the CLI text form (issue 3 item 1)."""

from __future__ import annotations

import numpy as np
import pytest

from frp_assess.errors import InputError
from frp_assess.motions.spectra import (
    EC8_TABLE,
    NTC_CC_TABLE,
    NTC_SS_TABLE,
    NTC_ST,
    PRESETS,
    damping_correction,
    ec8_spectrum,
    ntc2018_spectrum,
    ntc_ss,
    parse_spectrum,
    preset_spectrum,
    table_spectrum,
)


def test_ec8_issue_vector():
    """Issue 3: EC8 type 1, ground B, a_g = 0.25 g."""
    s = ec8_spectrum(0.25, "B", 1)
    assert s.sa(0.0) == pytest.approx(0.300)
    assert s.sa([0.15, 0.3, 0.5]) == pytest.approx([0.750] * 3)
    assert s.sa(1.0) == pytest.approx(0.375)
    assert s.sa(3.0) == pytest.approx(0.08333, abs=1e-5)
    assert s.pga_g == pytest.approx(0.300)


def test_ntc_issue_vector():
    """Issue 3: NTC a_g = 0.25 g, F0 = 2.4, T_C* = 0.30 s, soil C, T1."""
    s = ntc2018_spectrum(0.25, 2.4, 0.30, "C", "T1")
    assert s.parameters["S_S"] == pytest.approx(1.34)
    assert s.T_C == pytest.approx(0.4687, abs=1e-4)
    assert s.T_B == pytest.approx(s.T_C / 3)
    assert s.T_D == pytest.approx(2.60)
    assert s.plateau_g == pytest.approx(0.804)
    assert s.sa(0.3) == pytest.approx(0.804)
    assert s.sa(1.0) == pytest.approx(0.3768, abs=1e-4)


@pytest.mark.parametrize("stype,ground", [(t, g) for t in EC8_TABLE for g in EC8_TABLE[t]])
def test_ec8_table_branches(stype, ground):
    """Eqs. 3.2-3.5 with Table 3.2/3.3 values: corners, continuity, η scaling."""
    S, tb, tc, td = EC8_TABLE[stype][ground]
    ag = 0.2
    s = ec8_spectrum(ag, ground, stype)
    top = 2.5 * ag * S
    assert (s.T_B, s.T_C, s.T_D) == (tb, tc, td)
    assert s.sa(0.0) == pytest.approx(ag * S)
    assert s.sa([tb, (tb + tc) / 2, tc]) == pytest.approx([top] * 3)
    assert s.sa(td) == pytest.approx(top * tc / td)
    assert s.sa(2 * td) == pytest.approx(top * tc * td / (2 * td) ** 2)
    for corner in (tb, tc, td):  # continuous at the corners
        assert s.sa(corner * (1 + 1e-9)) == pytest.approx(s.sa(corner * (1 - 1e-9)), rel=1e-6)
    s10 = ec8_spectrum(ag, ground, stype, damping=0.10)
    eta = np.sqrt(10 / 15)
    assert s10.sa(tc) == pytest.approx(top * eta)
    assert s10.sa(0.0) == pytest.approx(ag * S)


@pytest.mark.parametrize("damping,expected", [(0.05, 1.0), (0.10, (10 / 15) ** 0.5), (0.0, 2**0.5)])
def test_damping_correction(damping, expected):
    """EN 1998-1 Eq. 3.6 / NTC Eq. 3.2.4."""
    assert damping_correction(damping) == pytest.approx(expected)


def test_damping_correction_lower_bound():
    assert damping_correction(0.40) == 0.55  # √(10/45) = 0.471 < 0.55


@pytest.mark.parametrize("soil", sorted(NTC_SS_TABLE))
def test_ntc_soil_tables(soil):
    """Tab. 3.2.IV: S_S = a − b·F0·a_g bounded; C_C = c·T_C*^e; T_B = T_C/3; T_D = 4a_g + 1.6."""
    a, b, lo, hi = NTC_SS_TABLE[soil]
    c, e = NTC_CC_TABLE[soil]
    for ag, F0 in [(0.05, 2.4), (0.15, 2.5), (0.35, 2.6)]:
        assert ntc_ss(soil, ag, F0) == pytest.approx(min(max(a - b * F0 * ag, lo), hi))
        s = ntc2018_spectrum(ag, F0, 0.35, soil)
        assert s.T_C == pytest.approx(c * 0.35**e * 0.35)
        assert s.T_D == pytest.approx(4 * ag + 1.6)
        assert s.pga_g == pytest.approx(ag * s.parameters["S_S"])
        assert s.plateau_g == pytest.approx(s.pga_g * F0)


def test_ntc_bounds_are_active():
    assert ntc_ss("D", 0.02, 2.4) == 1.80  # upper bound
    assert ntc_ss("D", 0.45, 2.6) == 0.90  # lower bound
    assert ntc_ss("B", 0.01, 2.4) == 1.20


@pytest.mark.parametrize("topo", sorted(NTC_ST))
def test_ntc_topography(topo):
    base = ntc2018_spectrum(0.2, 2.5, 0.3, "B", "T1")
    s = ntc2018_spectrum(0.2, 2.5, 0.3, "B", topo)
    assert s.sa([0.0, 0.5, 3.0]) == pytest.approx(base.sa([0.0, 0.5, 3.0]) * NTC_ST[topo])


@pytest.mark.parametrize("name", sorted(PRESETS))
def test_presets(name):
    """docs/model.md §6: a_g·S = 0.106 g, plateau 2.5·a_g·S on [T_B, T_C], T_D = 2 s."""
    ags, tb, tc = PRESETS[name]
    s = preset_spectrum(name.lower())
    assert s.pga_g == ags and s.T_B == tb and s.T_C == tc and s.T_D == 2.0
    assert s.sa([tb, tc]) == pytest.approx([2.5 * ags] * 2)
    assert s.sa(1.0) == pytest.approx(2.5 * ags * tc / 1.0)


def test_table_spectrum_interpolation_and_ends():
    s = table_spectrum([0.0, 0.2, 1.0], [0.3, 0.8, 0.4])
    assert s.sa([0.0, 0.1, 0.6, 1.0]) == pytest.approx([0.3, 0.55, 0.6, 0.4])
    assert s.sa(5.0) == pytest.approx(0.4)  # held constant beyond the last point
    assert s.pga_g == 0.3 and s.T_B is None


def test_table_spectrum_rejects_bad_points():
    with pytest.raises(InputError):
        table_spectrum([0.0, 0.0], [0.3, 0.4])
    with pytest.raises(InputError):
        table_spectrum([0.0, 1.0], [0.3, -0.1])


def test_vectorised_shape():
    T = np.linspace(0, 4, 12).reshape(3, 4)
    assert ec8_spectrum(0.1, "A").sa(T).shape == (3, 4)


@pytest.mark.parametrize(
    "text,kind,pga",
    [
        ("A2", "preset", 0.106),
        ("ec8:type=1,ground=B,ag=0.25", "ec8", 0.30),
        ("EC8: type=2, ground=d, ag=0.1, damping=0.05", "ec8", 0.18),
        ("ntc:ag=0.25,F0=2.4,tc=0.30,soil=C,topo=T1", "ntc2018", 0.25 * 1.34),
        ("ntc:ag=0.25,F0=2.4,tc=0.30,soil=C,topo=T4", "ntc2018", 0.25 * 1.34 * 1.4),
        ("table:0/0.3,0.5/0.75,2/0.2", "table", 0.3),
    ],
)
def test_parse_spectrum(text, kind, pga):
    s = parse_spectrum(text)
    assert s.kind == kind and s.pga_g == pytest.approx(pga)


@pytest.mark.parametrize(
    "text",
    [
        "A9",
        "ec8:type=3,ground=B,ag=0.2",
        "ec8:ground=F,ag=0.2",
        "ec8:ground=B",
        "ec8:ag=x",
        "ntc:ag=0.2,F0=2.4,tc=0.3",
        "ntc:ag=0.2,F0=2.4,tc=0.3,soil=B,topo=T7",
        "foo:bar",
        "ec8:ground=B,ag=0.2,colour=red",
        "table:0/0.3",
        "table:0-0.3,1-0.2",
        "ec8:ground=B,ag=-1",
    ],
)
def test_parse_spectrum_errors(text):
    with pytest.raises(InputError) as err:
        parse_spectrum(text)
    assert "\n" not in str(err.value)
