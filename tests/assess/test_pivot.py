"""The compression at the base of every case of an assessment (docs/model.md §1.1): a record,
never a reason to drop an option.

Hand calculations: W = w·B·H, T_u = E·ρ·B·c·ε_u, x = (W + T_u)/(0.85·f_d), f_d = f_m/FC with
f_m of Circolare 2019 Tab. C8.5.I (solid brick and lime mortar 2.6–4.3 MPa; LC1 minimum,
LC2/LC3 mean) and FC of Tab. C8.5.IV (1.35 / 1.20 / 1.00).
"""

from __future__ import annotations

from dataclasses import asdict, replace
from pathlib import Path

import pytest

from frp_assess.assess.cache import task_key
from frp_assess.assess.from_project import load_inputs
from frp_assess.assess.inputs import AssessmentInputs, Material, RetrofitOption
from frp_assess.assess.masonry_strength import DEFAULT_COMPRESSIVE_STRENGTH, masonry_strength
from frp_assess.assess.pivot_check import pivot_checks
from frp_assess.dynamics import IdaSettings, ModelOptions
from frp_assess.errors import InputError
from frp_assess.motions import preset_spectrum

CFRP = Material("CFRP", 150.0, 0.013, 1550.0, 35.0)
GFRP = Material("GFRP", 46.0, 0.015, 2000.0, 8.0)


def inputs(pivot: str = "crushing", **kw: object) -> AssessmentInputs:
    """The façade of issue 16: B = 0.25 m, H = 4.5 m, solid brick, LC1."""
    options = (
        RetrofitOption("CFRP external 3", CFRP, "external", 3.0),
        RetrofitOption("CFRP centred 1", CFRP, "centred", 1.0),
        RetrofitOption("CFRP external 1", CFRP, "external", 1.0),
        RetrofitOption("GFRP centred 0.5", GFRP, "centred", 0.5),
    )
    base = AssessmentInputs(
        thickness=0.25,
        height=4.5,
        unit_weight=18.0,
        mechanism="one-sided",
        spectrum=preset_spectrum("A2"),
        records=(),
        options=options,
        masonry="solid-brick-lime-mortar",
        model=ModelOptions(pivot=pivot),  # type: ignore[arg-type]
    )
    return replace(base, **kw)  # type: ignore[arg-type]


# ------------------------------------------------------------------------ the strength
def test_masonry_strength_rule_and_project_value() -> None:
    lc1 = masonry_strength("solid-brick-lime-mortar", "LC1")
    assert (lc1.f_m, lc1.confidence_factor) == (2.6, 1.35)
    assert lc1.f_d == pytest.approx(2.6 / 1.35)
    lc2 = masonry_strength("solid-brick-lime-mortar", "LC2")
    assert lc2.f_d == pytest.approx((2.6 + 4.3) / 2 / 1.20)
    given = masonry_strength("solid-brick-lime-mortar", "LC3", 5.0)
    assert given.f_d == 5.0 and "project value" in given.source
    none = masonry_strength(None, "LC2")
    assert none.f_m == DEFAULT_COMPRESSIVE_STRENGTH == 1.0  # rubble stone, LC1 minimum
    assert none.f_d == pytest.approx(1.0 / 1.20)
    with pytest.raises(InputError, match="compressive_strength"):
        masonry_strength(None, "LC1", -1.0)


# -------------------------------------------------------------------------- the checks
def test_pivot_checks_by_hand_and_consistent_with_the_model() -> None:
    inp = inputs()
    f_d = 2.6 / 1.35  # [MPa]
    weight = 18.0 * 0.25 * 4.5  # [kN/m]
    checks = pivot_checks(inp)
    assert [c.case for c in checks] == inp.case_names()
    for c, model in zip(checks, inp.case_models(), strict=True):
        assert c.check.weight == pytest.approx(weight)
        if c.case == "Unreinforced":
            assert c.check.bar_force == 0.0 and c.bar_distance is None
            assert c.check.depth == pytest.approx(weight / (0.85 * f_d * 1e3))
        if c.model_pivot == "crushing":  # kN and MPa here, N and Pa in the dynamics
            x_w = model.base_reaction.weight_depth
            assert x_w == pytest.approx(weight / (0.85 * f_d * 1e3), rel=1e-12)
    ext3, cen1, ext1, gfrp = checks[1:]
    # CFRP external 3 ‰ (issue 16): T_u = 150e6 kPa · 3e-3 · 0.25 m · 0.5 · 0.013 = 731 kN/m
    t_u = 150e6 * 3e-3 * 0.25 * 0.5 * 0.013
    assert ext3.check.bar_force == pytest.approx(t_u)
    assert ext3.check.depth == pytest.approx((weight + t_u) / (0.85 * f_d * 1e3))
    # x at T_u beyond the bar: the toe crushes before the bar breaks; computed, not dropped
    assert ext3.check.depth > 0.25 and ext3.model_pivot == "crushing"
    assert "the toe crushes before the bar breaks" in ext3.line()
    # CFRP 1 ‰: x = (20.25 + 243.75)/1637 = 0.161 m: beyond B/2 = 0.125, inside B
    assert cen1.check.depth == pytest.approx((weight + t_u / 3) / (0.85 * f_d * 1e3))
    assert "the toe crushes before the bar breaks" in cen1.line()
    assert "the toe crushes" not in ext1.line() and "the toe crushes" not in gfrp.line()
    # the record of results.json: every field a JSON value, the verdict in one line
    rec = asdict(ext1.result())
    assert rec["pivot_shift"] == pytest.approx(weight / (0.85 * f_d * 1e3) / 2)  # x_W/2
    assert rec["model_pivot"] == "crushing"
    assert all(c.result().dropped is False for c in checks)
    assert "\n" not in rec["reason"]
    assert asdict(inp.masonry_strength)["f_d"] == pytest.approx(f_d)


def test_edge_rule_flags_but_keeps_a_deep_zone() -> None:
    checks = pivot_checks(inputs("edge"))
    assert all(c.model_pivot == "edge" for c in checks)
    assert "the edge pivot holds" in checks[0].line()  # unreinforced x/B = 0.05
    # GFRP 0.5 ‰: x/B = 0.155 > 0.10, said, and the option is still computed and ranked
    assert all("the edge model ignores" in c.line() for c in checks[1:])
    assert all(c.result().dropped is False for c in checks)


def test_cache_key_follows_the_weights_depth() -> None:
    record, ida = "0" * 64, IdaSettings()
    weak, strong = inputs(compressive_strength=1.0), inputs(compressive_strength=4.0)
    option = weak.options[2]
    assert task_key(weak.model_for(option), record, ida) != task_key(
        strong.model_for(option), record, ida
    )
    # with the edge pivot the strength changes nothing, so cached results stay valid
    e_weak = inputs("edge", compressive_strength=1.0)
    e_strong = inputs("edge", compressive_strength=4.0)
    assert task_key(e_weak.model_for(option), record, ida) == task_key(
        e_strong.model_for(option), record, ida
    )


def test_project_keys_reach_the_inputs(tmp_path: Path) -> None:
    text = (Path(__file__).parents[2] / "projects" / "facade-laquila.yaml").read_text()
    inp = load_inputs(Path(__file__).parents[2] / "projects" / "facade-laquila.yaml", warn=None)
    assert inp.model.pivot == "crushing"  # the default
    assert inp.masonry_strength.f_d == pytest.approx((2.6 + 4.3) / 2 / 1.20)  # LC2
    changed = text.replace(
        "  mechanism: one-sided\n",
        "  mechanism: one-sided\n  compressive_strength: 2.0\n",
        1,
    ).replace("analysis:\n", "analysis:\n  pivot: edge\n", 1)
    (tmp_path / "records").symlink_to(Path(__file__).parents[2] / "projects" / "records")
    path = tmp_path / "p.yaml"
    path.write_text(changed)
    inp = load_inputs(path, warn=None)
    assert inp.model.pivot == "edge"
    assert inp.compressive_strength == 2.0
    assert inp.masonry_strength.f_d == pytest.approx(2.0 / 1.20)
