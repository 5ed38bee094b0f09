"""The bar rules against hand calculations (SI units).

Sources: docs/model.md §2 (the paper's Eqs. 7–9: b_r = B/2 centred, B external; A = ρ·B·1 m
per line, one line centred and one per face external; T = E·A·e/H; ε_max = c·ε_u) and
§2.1 (CNR-DT 200 R1/2013 §3.5: ε_fd = η_a·ε_fk/γ_f, γ_f = 1.10 of Table 3.1).
"""

from __future__ import annotations

import pytest

from frp_assess.rules.bars import (
    DEFAULT_STRAIN_FACTOR,
    FRP_RUPTURE_PARTIAL_FACTOR,
    bar_area,
    bar_force,
    characteristic_strain,
    design_rupture_strain,
    elongation_strain,
    eta_a,
    faces,
    fd_strain,
    lever_arm,
    rupture_strain,
)


def test_lever_arm_and_faces() -> None:
    assert lever_arm("centred", 0.4) == pytest.approx(0.2)
    assert lever_arm("external", 0.4) == pytest.approx(0.4)
    assert (faces("centred"), faces("external")) == (1, 2)
    with pytest.raises(ValueError, match="centred"):
        lever_arm("inside", 0.4)


def test_area_and_force_by_hand() -> None:
    # CFRP external 3 ‰ on B = 0.25 m: A = 7.5e-4 m²/m; E = 150 GPa at ε = 0.0065:
    # T = 150e9 · 7.5e-4 · 0.0065 = 731.25 kN/m
    area = bar_area(3.0, 0.25)
    assert area == pytest.approx(7.5e-4)
    assert bar_force(150e9, area, 0.0065) == pytest.approx(731.25e3)
    # e = 3 mm over H = 3 m: ε = 1e-3, T = 46e9 · 4e-4 · 1e-3 = 18.4 kN/m (GFRP 1 ‰, B = 0.4)
    assert bar_force(46e9, bar_area(1.0, 0.4), elongation_strain(0.003, 3.0)) == pytest.approx(
        18.4e3
    )


def test_rupture_strains() -> None:
    assert DEFAULT_STRAIN_FACTOR == 0.5
    assert rupture_strain(0.015, 0.5) == pytest.approx(0.0075)  # GFRP mean, c·ε_u
    # CFRP external exposure: η_a = 0.85, ε_fk = 0.012: ε_fd = 0.85·0.012/1.10 = 0.0092727
    assert FRP_RUPTURE_PARTIAL_FACTOR == 1.10
    assert fd_strain(0.012, 0.85) == pytest.approx(0.0092727, abs=1e-7)
    assert design_rupture_strain(0.012, 0.85, 0.5) == pytest.approx(0.0046364, abs=1e-7)
    # one rule: the design value is c·ε_fd, to the last bit
    assert design_rupture_strain(0.012, 0.85, 0.7) == rupture_strain(fd_strain(0.012, 0.85), 0.7)


def test_characteristic_strain_is_the_5_percent_fractile() -> None:
    # ε_u = 0.015, CoV 0.10: 0.015·(1 − 0.1645) = 0.0125325
    assert characteristic_strain(0.015, 0.10) == pytest.approx(0.0125325)
    with pytest.raises(ValueError):
        characteristic_strain(0.015, 0.7)


#: CNR-DT 200 R1/2013 Table 3.2, typed from the document: η_a (internal, external, aggressive)
TABLE_3_2 = {
    "glass": (0.75, 0.65, 0.50),
    "carbon": (0.95, 0.85, 0.85),
    "aramid": (0.85, 0.75, 0.70),
}


@pytest.mark.parametrize(
    "fibre,exposure,eta",
    [
        (fibre, exposure, etas[i])
        for fibre, etas in TABLE_3_2.items()
        for i, exposure in enumerate(("internal", "external", "aggressive"))
    ],
)
def test_eta_a_is_table_3_2(fibre: str, exposure: str, eta: float) -> None:
    assert eta_a(fibre, exposure) == eta


def test_eta_a_of_a_fibre_not_in_the_table_is_a_key_error() -> None:
    with pytest.raises(KeyError):
        eta_a("basalt", "internal")  # the product's choice for basalt is not the table's
