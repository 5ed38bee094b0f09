"""Bar catalogue, layout rounding, design strain and anchorage (hand calculations).

Environmental conversion factors typed from CNR-DT 200 R1/2013 Table 3.2 (η_a for internal /
external / aggressive exposure): glass 0.75 / 0.65 / 0.50, carbon 0.95 / 0.85 / 0.85,
aramid 0.85 / 0.75 / 0.70.  γ_f = 1.10 for FRP rupture (Table 3.1).
"""

from __future__ import annotations

import math

import pytest

from frp_assess.assess.bar_anchorage import anchorage, bar_rupture_force, cone_area
from frp_assess.assess.bar_catalogue import (
    BAR_CATALOGUE,
    BarSize,
    bar_layout,
    bar_size,
    bar_sizes,
    best_layout,
)
from frp_assess.assess.bar_strain import bar_design_strain, environmental_factor
from frp_assess.errors import InputError
from frp_assess.rules.bars import characteristic_strain
from tests.rules.test_bars import TABLE_3_2  # η_a of CNR-DT 200 Table 3.2, typed once


@pytest.mark.parametrize(
    "material,fibre", [("GFRP", "glass"), ("CFRP", "carbon"), ("AFRP", "aramid"), ("BFRP", "glass")]
)
def test_environmental_factors_against_cnr_dt_200_table(material, fibre):
    for exposure, eta in zip(("internal", "external", "aggressive"), TABLE_3_2[fibre], strict=True):
        assert environmental_factor(material, exposure) == eta


def test_unknown_exposure_or_material_is_an_input_error():
    with pytest.raises(InputError, match="internal, external, aggressive"):
        environmental_factor("GFRP", "marine")
    with pytest.raises(InputError, match="GFRP"):
        environmental_factor("steel", "internal")


def test_design_rupture_strain_by_hand():
    # GFRP, external: 0.5 · 0.65 · 0.015 / 1.10 = 0.0044318
    d = bar_design_strain(0.015, "GFRP", "external")
    assert d.design == pytest.approx(0.5 * 0.65 * 0.015 / 1.10)
    assert d.design == pytest.approx(0.0044318, abs=1e-7)
    # CFRP internal without partial factor: 0.5 · 0.95 · 0.013 = 0.006175
    assert bar_design_strain(0.013, "CFRP", "internal", partial_factor=1.0).design == pytest.approx(
        0.006175
    )
    assert characteristic_strain(0.015, 0.05) == pytest.approx(0.015 * (1 - 1.645 * 0.05))


def test_catalogue_areas_and_project_sizes():
    for sizes in BAR_CATALOGUE.values():
        for s in sizes:
            assert s.area == pytest.approx(math.pi * s.diameter**2 / 4)
    assert bar_size("GFRP", 12).area == pytest.approx(113.097, abs=1e-3)
    own = BarSize("GFRP", 12.0, 110.0, "producer X data sheet")
    assert bar_size("GFRP", 12, [own]).area == 110.0  # replaces the catalogue's
    assert [s.diameter for s in bar_sizes("GFRP", [BarSize("GFRP", 7.0, 38.0)])][:3] == [
        6.0,
        7.0,
        8.0,
    ]
    with pytest.raises(InputError, match="available: 6, 8, 10"):
        bar_size("CFRP", 20)
    with pytest.raises(InputError):
        bar_sizes("AFRP")


def test_layout_rounds_up_to_whole_bars():
    # ρ = 1 ‰, B = 0.25 m, L = 5 m: 1250 mm² per line; Ø10 = 78.54 mm² → 15.9 → 16 bars
    lay = bar_layout(1.0, 0.25, 5.0, "centred", 10.0)
    assert lay.bars_per_line == 16 and lay.lines == 1 and lay.total_bars == 16
    assert lay.spacing == pytest.approx(5.0 / 16)
    assert lay.ratio_installed == pytest.approx(16 * math.pi * 25 / 1250)  # 1.0053 ‰
    assert lay.ratio_installed > lay.ratio_asked
    assert lay.governed_by == "ratio" and lay.fits


def test_layout_exact_fit_does_not_gain_a_bar():
    # 0.2 ‰ · 0.25 m · 6 m = 300 mm² (300.00000000000006 in floating point), bars of 30 mm²
    lay = bar_layout(0.2, 0.25, 6.0, "centred", 6.0, bar_area=30.0)
    assert lay.bars_per_line == 10
    assert lay.ratio_installed == pytest.approx(0.2)


def test_layout_largest_spacing_governs():
    # 0.1 ‰ · 0.25 · 6 = 150 mm²: one Ø16 (201 mm²) would do, but s ≤ 1 m needs 6 bars
    lay = bar_layout(0.1, 0.25, 6.0, "centred", 16.0)
    assert lay.bars_per_line == 6 and lay.spacing == pytest.approx(1.0)
    assert lay.governed_by == "max_spacing"
    assert lay.ratio_installed == pytest.approx(6 * math.pi * 64 / 1500)


def test_layout_below_smallest_spacing_does_not_fit():
    # 3 ‰ · 0.4 · 1 = 1200 mm² with Ø6 (28.27 mm²): 43 bars at 23 mm
    lay = bar_layout(3.0, 0.4, 1.0, "centred", 6.0)
    assert lay.bars_per_line == 43 and not lay.fits
    assert "larger diameter" in lay.note


def test_external_layout_quantities():
    # two faces; bar 3.6 m (H = 3 m + 2·0.3 m anchorage), GFRP 2000 kg/m³, 8 EUR/kg
    lay = bar_layout(
        1.0, 0.25, 5.0, "external", 10.0,
        bar_length=3.6, density=2000.0, price=8.0, installation_per_metre=150.0,
    )  # fmt: skip
    assert lay.lines == 2 and lay.total_bars == 32
    assert lay.metres == pytest.approx(32 * 3.6)
    mass = 32 * 3.6 * (math.pi * 25e-6) * 2000.0  # m · m² · kg/m³
    assert lay.mass == pytest.approx(mass)
    assert lay.cost == pytest.approx(mass * 8.0 + 150.0 * 5.0 * 2)
    assert bar_layout(1.0, 0.25, 5.0, "external", 10.0).mass is None


def test_best_layout_picks_the_least_installed_ratio_that_fits():
    sizes = bar_sizes("GFRP")
    best = best_layout(1.0, 0.25, 5.0, "centred", sizes)
    assert best is not None and best.fits
    for s in sizes:
        lay = bar_layout(1.0, 0.25, 5.0, "centred", s.diameter)
        if lay.fits:
            assert best.ratio_installed <= lay.ratio_installed + 1e-12
    assert best_layout(30.0, 0.5, 1.0, "centred", sizes[:1]) is None


def test_rupture_force_and_bond_lengths_by_hand():
    # Ø10 GFRP: 78.54 mm² · 46 GPa · 0.0075 = 27.1 kN
    f = bar_rupture_force(math.pi * 25, 46.0, 0.0075)
    assert f == pytest.approx(78.5398 * 46 * 0.0075, rel=1e-5)
    a = anchorage(
        f, 10.0, hole_diameter=16.0, bond_bar=8.0, bond_masonry=0.5,
        tensile_strength=0.1, thickness=0.4, spacing=0.3, position="centred",
    )  # fmt: skip
    assert a.length_bar == pytest.approx(f * 1e3 / (math.pi * 10 * 8.0) / 1e3)  # 0.108 m
    assert a.length_masonry == pytest.approx(f * 1e3 / (math.pi * 16 * 0.5) / 1e3)  # 1.08 m
    assert a.length_required == a.length_masonry and a.length_ok
    # cone radius 1.08 m ≫ B/2 and s/2: the base is the whole strip B·s = 0.12 m²
    assert a.cone_area == pytest.approx(0.4 * 0.3)
    assert a.cone_resistance == pytest.approx(0.1e3 * 0.12)  # 12 kN < 27 kN
    assert not a.cone_ok


def test_cone_area_unclipped_half_and_strip():
    assert cone_area(0.1, (1.0, 1.0), 5.0) == pytest.approx(math.pi * 0.01)
    assert cone_area(0.1, (0.0, 1.0), 5.0) == pytest.approx(math.pi * 0.01 / 2)
    # circle r = 0.1 cut by |y| ≤ 0.05: 2·∫ min(√(r²−x²), 0.05)·2 dx, by the segment formula:
    # area = πr² − 2·(r²·acos(h/r) − h·√(r²−h²)) with h = 0.05
    r, h = 0.1, 0.05
    expect = math.pi * r * r - 2 * (r * r * math.acos(h / r) - h * math.sqrt(r * r - h * h))
    assert cone_area(r, (1.0, 1.0), 2 * h) == pytest.approx(expect)


def test_short_provided_length_is_flagged():
    a = anchorage(
        20.0, 10.0, hole_diameter=10.0, bond_bar=8.0, bond_masonry=8.0,
        tensile_strength=0.2, thickness=0.4, spacing=0.5, position="external",
        axis_to_face=0.02, length=0.05,
    )  # fmt: skip
    assert a.length_required == pytest.approx(20e3 / (math.pi * 10 * 8.0) / 1e3)
    assert not a.length_ok
