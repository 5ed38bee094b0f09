"""Masonry table, knowledge-level rule and the pivot (hand calculations).

Values typed from Circolare 2019 Tab. C8.5.I (solid brick and lime mortar: f_m 2.6–4.3 MPa,
E 1200–1800 MPa, w 18 kN/m³), Tab. C8.5.IV (FC 1.35 / 1.20 / 1.00) and §C8.5.4.1 (LC1: least
strength, mean E; LC2/LC3: means).  Stress block 0.85·f_d over the depth x at the pivot.
"""

from __future__ import annotations

import pytest

from frp_assess.assess.masonry_strength import (
    MASONRY_TABLE,
    masonry_design_values,
    masonry_strength,
    pivot_check,
)
from frp_assess.config.library import MASONRY
from frp_assess.errors import InputError
from frp_assess.rules.bars import bar_area
from frp_assess.rules.bars import bar_force as rule_bar_force
from frp_assess.rules.masonry import wall_weight


def bar_force(ratio: float, thickness: float, modulus_gpa: float, strain: float) -> float:
    """T = E·ρ·B·ε [kN/m] of the rules, with E in kPa (GPa·1e6) so that T comes in kN/m."""
    return rule_bar_force(modulus_gpa * 1e6, bar_area(ratio, thickness), strain)


def test_table_covers_the_library_and_agrees_on_unit_weight():
    for key, m in MASONRY.items():
        row = MASONRY_TABLE[key]
        lo, hi = row.unit_weight
        assert lo <= m.unit_weight <= hi, key
    for row in MASONRY_TABLE.values():
        for lo, hi in (row.f_m, row.tau_0, row.elastic_modulus, row.unit_weight):
            assert 0 < lo <= hi


def test_solid_brick_row_as_typed_from_the_circolare():
    row = MASONRY_TABLE["solid-brick-lime-mortar"]
    assert row.f_m == (2.6, 4.3)
    assert row.elastic_modulus == (1200.0, 1800.0)
    assert row.unit_weight == (18.0, 18.0)


@pytest.mark.parametrize(
    "level,f_m,fc",
    [("LC1", 2.6, 1.35), ("LC2", (2.6 + 4.3) / 2, 1.20), ("LC3", (2.6 + 4.3) / 2, 1.00)],
)
def test_knowledge_level_rule(level, f_m, fc):
    v = masonry_design_values("solid-brick-lime-mortar", level)
    assert v.f_m == pytest.approx(f_m)
    assert v.elastic_modulus == pytest.approx((1200 + 1800) / 2)  # mean at every level
    assert v.confidence_factor == fc
    assert v.f_d == pytest.approx(f_m / fc)
    assert v.from_project == ()


def test_project_value_overrides_the_table_and_partial_factor_divides():
    v = masonry_design_values("rubble-stone", "LC3", f_m=3.1, partial_factor=2.0)
    assert v.f_m == 3.1
    assert v.f_d == pytest.approx(3.1 / (1.0 * 2.0))
    assert v.elastic_modulus == pytest.approx((690 + 1050) / 2)
    assert v.from_project == ("f_m",)


def test_unknown_masonry_and_level_are_one_line_input_errors():
    with pytest.raises(InputError) as e:
        masonry_design_values("adobe")
    assert "\n" not in str(e.value) and str(e.value).startswith("wall.masonry: ")
    with pytest.raises(InputError, match="LC1, LC2 or LC3"):
        masonry_design_values("rubble-stone", "LC4")


def test_issue_example_cfrp_external_3_permille_crushes_the_pivot():
    # B = 0.25 m, H = 3 m, w = 18 kN/m³, CFRP E = 150 GPa, ε = 0.5·0.013 = 0.0065, ρ = 3 ‰
    w_hand = 18 * 0.25 * 3  # 13.5 kN/m
    t_hand = 150e6 * (3e-3 * 0.25) * 0.0065  # kN/m² · m²/m = 731.25 kN/m
    assert wall_weight(18, 0.25, 3) == pytest.approx(13.5)
    assert bar_force(3.0, 0.25, 150.0, 0.0065) == pytest.approx(731.25)
    f_d = 2.6 / 1.35  # LC1 solid brick [MPa]
    x_hand = (w_hand + t_hand) / (0.85 * f_d * 1000)  # 744.75 / 1637.04 = 0.455 m
    chk = pivot_check(w_hand, t_hand, 0.25, f_d)
    assert chk.force == pytest.approx(744.75)
    assert chk.depth == pytest.approx(x_hand)
    assert chk.depth == pytest.approx(0.4549, abs=1e-4)
    assert chk.depth_ratio > 1 and not chk.rigid_block_holds
    assert "fails" in chk.reason


def test_pivot_check_unreinforced_holds_gfrp_at_rupture_does_not():
    # B = 0.4 m, H = 3 m, w = 18: W = 21.6 kN/m; LC2 solid brick f_d = 3.45/1.2 = 2.875 MPa
    f_d = 3.45 / 1.2
    bare = pivot_check(21.6, 0.0, 0.4, f_d)
    assert bare.depth == pytest.approx(21.6 / 2443.75)  # 0.85·2.875 MPa = 2443.75 kN/m²
    assert bare.rigid_block_holds
    # GFRP centred 1 ‰ at rupture: T = 46e6 · 4e-4 · 0.0075 = 138 kN/m, x = 159.6/2443.75
    t = bar_force(1.0, 0.4, 46.0, 0.0075)
    assert t == pytest.approx(138.0)
    gfrp = pivot_check(21.6, t, 0.4, f_d)
    assert gfrp.depth == pytest.approx(0.06531, abs=1e-5)
    assert gfrp.depth_ratio == pytest.approx(0.1633, abs=1e-4)
    assert not gfrp.rigid_block_holds
    assert pivot_check(21.6, t, 0.4, f_d, limit=0.2).rigid_block_holds


@pytest.mark.parametrize("call", ["design_values", "strength"])
def test_an_unknown_knowledge_level_is_reported_on_the_project_key(call: str) -> None:
    """The project sets the level in ``code_check.knowledge_level`` (there is no
    ``wall.knowledge_level``): both entry points name that key."""
    with pytest.raises(InputError) as info:
        if call == "design_values":
            masonry_design_values("rubble-stone", "LC4")
        else:
            masonry_strength("rubble-stone", "LC4")
    assert info.value.key == "code_check.knowledge_level"
    assert "LC4" in info.value.message
