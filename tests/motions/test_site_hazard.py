"""Seismic parameters from coordinates (frp_assess.motions.site) against independent values.

The node values below were read by hand from the published grid (NTC 2008 Allegato B, as
shipped in HazardNTCgrid_IT.mat of the bimquake 1.0.0 wheel; a_g in g/10 as published) and
typed here; the distances are great-circle on a sphere of 6371 km, computed separately; the
expected site values are the Allegato A formulas worked out by hand from those numbers.
"""

from __future__ import annotations

import math

import pytest

from frp_assess.errors import InputError
from frp_assess.motions.site import OutsideGridError, site_hazard
from frp_assess.motions.site import grid as grid_module
from frp_assess.motions.site.formulas import (
    C_U,
    T_R,
    V_R,
    clamp_return_period,
    inverse_distance_mean,
    log_interpolation,
)
from frp_assess.motions.site.grid import GridDataError, load_grid, nearest_nodes
from frp_assess.motions.site.hazard import parameters_at

# (lon, lat [°], distance from the site [km], a_g(201) [g/10], F0(201), T_C*(201) [s],
#  a_g(475) [g/10], F0(475), T_C*(475) [s]) of the 4 nodes nearest each site, nearest first
NODES = {
    # L'Aquila, 42.35 N 13.40 E
    (42.35, 13.40): [
        (13.42252, 42.33493, 2.4967, 1.9075, 2.3152, 0.31802, 2.6099, 2.364, 0.34696),
        (13.35486, 42.33487, 4.0736, 1.902, 2.3129, 0.31678, 2.6042, 2.3625, 0.34578),
        (13.42249, 42.38493, 4.3011, 1.9065, 2.3156, 0.3181, 2.6078, 2.3646, 0.34684),
        (13.35477, 42.38487, 5.3704, 1.904, 2.314, 0.3171, 2.606, 2.3627, 0.3462),
    ],
    # Milano, 45.464 N 9.19 E
    (45.464, 9.19): [
        (9.217374, 45.45929, 2.1982, 0.39655, 2.6215, 0.25244, 0.51502, 2.6473, 0.27953),
        (9.146319, 45.45675, 3.5009, 0.37532, 2.6325, 0.24762, 0.47941, 2.6665, 0.28006),
        (9.213706, 45.50923, 5.3581, 0.39091, 2.6238, 0.25007, 0.50801, 2.6455, 0.27893),
        (9.142559, 45.5067, 6.0185, 0.3682, 2.6368, 0.24505, 0.46919, 2.6679, 0.28005),
    ],
    # Catania, 37.502 N 15.087 E
    (37.502, 15.087): [
        (15.06152, 37.52357, 3.2869, 1.4444, 2.4296, 0.30958, 2.0358, 2.4868, 0.35245),
        (15.06039, 37.47357, 3.9378, 1.3515, 2.5137, 0.31899, 2.1332, 2.4219, 0.36665),
        (15.12437, 37.52262, 4.0152, 1.4289, 2.4271, 0.30985, 2.0128, 2.483, 0.35043),
        (15.12318, 37.47263, 4.5668, 1.3308, 2.5113, 0.31771, 2.093, 2.4208, 0.36631),
    ],
}
# a_g [g] by hand: Σ(p_i/d_i)/Σ(1/d_i) of the values above at T_R = 475 and 201 years, then
# SLV (T_R = −50/ln 0.9 = 474.56 years) by log(p) = log(p201) + log(p475/p201)·
# log(T_R/201)/log(475/201)
HAND = {
    (42.35, 13.40): (0.2607445, 0.1905401, 0.2606566),
    (45.464, 9.19): (0.04975554, 0.03857325, 0.04974193),
    (37.502, 15.087): (0.2066526, 0.1393409, 0.2065651),
}


@pytest.mark.parametrize("site", list(NODES), ids=["L'Aquila", "Milano", "Catania"])
def test_four_nearest_nodes_are_the_ones_read_by_hand(site: tuple[float, float]) -> None:
    nodes = nearest_nodes(*site)
    assert [(n.lon, n.lat) for n in nodes] == [(row[0], row[1]) for row in NODES[site]]
    for n, row in zip(nodes, NODES[site], strict=True):
        assert n.distance == pytest.approx(row[2], abs=1e-4)


@pytest.mark.parametrize("site", list(NODES), ids=["L'Aquila", "Milano", "Catania"])
def test_inverse_distance_mean_matches_the_hand_calculation(site: tuple[float, float]) -> None:
    nodes = nearest_nodes(*site)
    ag475, f0_475, tc475 = parameters_at(nodes, 475.0)
    ag201, _, _ = parameters_at(nodes, 201.0)
    a475_hand, a201_hand, slv_hand = HAND[site]
    assert ag475 == pytest.approx(a475_hand, rel=2e-6)
    assert ag201 == pytest.approx(a201_hand, rel=2e-6)
    rows = NODES[site]
    w = [1 / r[2] for r in rows]
    f0_hand = sum(r[7] * wi for r, wi in zip(rows, w, strict=True)) / sum(w)
    tc_hand = sum(r[8] * wi for r, wi in zip(rows, w, strict=True)) / sum(w)
    assert f0_475 == pytest.approx(f0_hand, rel=1e-6)
    assert tc475 == pytest.approx(tc_hand, rel=1e-6)
    # the full chain: V_N = 50, class II, SLV
    assert site_hazard(*site)["SLV"].ag == pytest.approx(slv_hand, rel=2e-6)


def test_return_periods_of_nominal_life_50_class_ii() -> None:
    """NTC 2018 Tab. 3.2.I with V_R = 50 years: T_R = 30, 50, 475, 975 years (rounded)."""
    h = site_hazard(42.35, 13.40, 50.0, "II")
    exact = {s: -50.0 / math.log(1.0 - p) for s, p in
             {"SLO": 0.81, "SLD": 0.63, "SLV": 0.10, "SLC": 0.05}.items()}  # fmt: skip
    assert exact["SLO"] == pytest.approx(30.11, abs=0.005)
    assert exact["SLV"] == pytest.approx(474.56, abs=0.005)
    for state, rounded in {"SLO": 30, "SLD": 50, "SLV": 475, "SLC": 975}.items():
        assert h[state].TR == pytest.approx(exact[state], rel=1e-12)
        assert round(h[state].TR) == rounded
    assert (h.V_R, h.C_U) == (50.0, 1.0)


def test_reference_period_and_use_classes() -> None:
    """NTC 2018 Tab. 2.4.II and §2.4.3 (V_R >= 35 years)."""
    assert [C_U(c) for c in ("I", "II", "III", "IV")] == [0.7, 1.0, 1.5, 2.0]
    assert V_R(50.0, 0.7) == 35.0
    assert V_R(10.0, 1.0) == 35.0  # below 35 years: 35
    assert V_R(100.0, 2.0) == 200.0
    assert T_R(200.0, 0.10) == pytest.approx(1898.24, abs=0.01)
    with pytest.raises(ValueError, match="use class"):
        C_U("V")


def test_return_period_clamped_to_the_grid() -> None:
    assert clamp_return_period(21.0) == 30
    assert clamp_return_period(3899.0) == 2475
    assert clamp_return_period(474.56) == 474.56
    h = site_hazard(42.35, 13.40, 100.0, "IV")  # V_R = 200: SLC T_R = 3899 years
    assert h["SLC"].TR == pytest.approx(-200 / math.log(0.95))
    assert h["SLC"].TR_used == 2475


def test_site_on_a_node_takes_the_node_values_exactly() -> None:
    # node at 13.42252 E, 42.33493 N: a_g(30) = 0.78911 g/10, F0(30) = 2.3995,
    # T_C*(30) = 0.27228 s; a_g(475) = 2.6099 g/10, F0 = 2.364, T_C* = 0.34696 s
    nodes = nearest_nodes(42.33493, 13.42252)
    assert nodes[0].distance == 0.0
    assert parameters_at(nodes, 475.0) == (2.6099 / 10, 2.364, 0.34696)
    slo = site_hazard(42.33493, 13.42252, 10.0, "I")["SLO"]  # V_R = 35: T_R = 21 -> 30
    assert (slo.TR_used, slo.ag, slo.F0, slo.Tc_star) == (30, 0.78911 / 10, 2.3995, 0.27228)


def test_log_interpolation_closed_form() -> None:
    # between (201, 1.9075) and (475, 2.6099) at T_R = 300:
    # ln(2.6099/1.9075) = 0.31352, ln(300/201) = 0.40047, ln(475/201) = 0.86000:
    # 1.9075·exp(0.31352·0.40047/0.86000) = 1.9075·exp(0.14600) = 2.2074 (by hand)
    assert log_interpolation(300.0, 201.0, 1.9075, 475.0, 2.6099) == pytest.approx(2.2074, abs=1e-4)
    assert log_interpolation(201.0, 201.0, 1.9075, 475.0, 2.6099) == 1.9075
    assert log_interpolation(475.0, 201.0, 1.9075, 475.0, 2.6099) == 2.6099
    assert inverse_distance_mean([1.0, 2.0], [1.0, 1.0]) == 1.5
    assert inverse_distance_mean([1.0, 2.0], [1.0, 3.0]) == pytest.approx((1 + 2 / 3) / (4 / 3))
    assert inverse_distance_mean([1.0, 2.0], [0.0, 3.0]) == 1.0


@pytest.mark.parametrize(
    ("lat", "lon", "where"),
    [
        (39.22, 9.11, "Cagliari (Sardinia: Allegato B Tab. 1)"),
        (38.47, 14.95, "Lipari"),
        (35.50, 12.60, "Lampedusa"),
        (42.50, 15.00, "the middle of the Adriatic"),
        (48.85, 2.35, "Paris"),
    ],
)
def test_a_site_off_the_grid_is_refused(lat: float, lon: float, where: str) -> None:
    with pytest.raises(OutsideGridError, match="outside the NTC reference grid") as exc:
        site_hazard(lat, lon)
    assert isinstance(exc.value, InputError)
    assert "\n" not in str(exc.value)


@pytest.mark.parametrize(
    ("lat", "lon"),
    [(45.437, 12.335), (45.65, 13.78), (38.11, 15.65), (40.146, 18.49), (40.55, 14.24)],
    ids=["Venezia", "Trieste", "Reggio Calabria", "Otranto", "Capri"],
)
def test_coastal_towns_and_the_islands_of_the_grid_are_accepted(lat: float, lon: float) -> None:
    assert site_hazard(lat, lon)["SLV"].ag > 0


def test_bad_coordinates_are_refused() -> None:
    with pytest.raises(InputError, match="latitude"):
        site_hazard(91.0, 13.0)
    with pytest.raises(InputError, match="longitude"):
        site_hazard(42.0, float("nan"))


def test_a_changed_grid_file_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    load_grid.cache_clear()
    monkeypatch.setattr(grid_module, "GRID_SHA256", "0" * 64)
    try:
        with pytest.raises(GridDataError, match="SHA-256"):
            load_grid()
    finally:
        load_grid.cache_clear()


# the independent second implementation (the cell found by brute force): tests/site/
