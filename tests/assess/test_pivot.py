"""The pivot check of an assessment and its drop rule (docs/model.md §1.1).

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
from frp_assess.assess.inputs import AssessmentInputs, Material, Option
from frp_assess.assess.masonry import DEFAULT_COMPRESSIVE_STRENGTH, masonry_strength
from frp_assess.assess.pivot import largest_ratio, pivot_checks, pivot_fails
from frp_assess.dynamics import IdaSettings, ModelOptions
from frp_assess.errors import InputError
from frp_assess.motions import preset_spectrum

CFRP = Material("CFRP", 150.0, 0.013, 1550.0, 35.0)
GFRP = Material("GFRP", 46.0, 0.015, 2000.0, 8.0)


def inputs(pivot: str = "crushing", **kw: object) -> AssessmentInputs:
    """The façade of issue 16: B = 0.25 m, H = 4.5 m, solid brick, LC1."""
    options = (
        Option("CFRP external 3", CFRP, "external", 3.0),
        Option("CFRP centred 1", CFRP, "centred", 1.0),
        Option("CFRP external 1", CFRP, "external", 1.0),
        Option("GFRP centred 0.5", GFRP, "centred", 0.5),
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


# ---------------------------------------------------------------------------- drop rule
def test_edge_rule_fails_beyond_a_tenth_of_b() -> None:
    assert pivot_fails("edge", 0.025, 0.25, 0.125) is None  # x/B = 0.10: holds
    reason = pivot_fails("edge", 0.026, 0.25, 0.125)
    assert reason is not None and reason.startswith("x/B = 0.104 > 0.10")
    assert pivot_fails("edge", 0.05, 0.25, None, limit=0.25) is None


@pytest.mark.parametrize(
    "depth,distance,dropped",
    [
        (0.124, 0.125, False),  # centred bar just outside the zone
        (0.125, 0.125, True),  # centred bar on its edge: in compression
        (0.20, 0.25, False),  # external bar, x < B: the crushing pivot carries it
        (0.25, 0.25, True),  # x = B: no mechanism
        (0.30, None, True),  # unreinforced, x > B
        (0.20, None, False),
    ],
)
def test_crushing_rule_fails_when_the_bar_is_compressed_or_x_reaches_b(
    depth: float, distance: float | None, dropped: bool
) -> None:
    reason = pivot_fails("crushing", depth, 0.25, distance)
    assert (reason is not None) == dropped
    if dropped:
        assert "\n" not in reason  # type: ignore[operator]
        assert ("no rocking mechanism" in reason) == (depth >= 0.25)  # type: ignore[operator]


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
            assert model.pivot.depth == pytest.approx(c.check.depth, rel=1e-12)
    ext3, cen1, ext1, gfrp = checks[1:]
    # CFRP external 3 ‰ (issue 16): T_u = 150e6 kPa · 3e-3 · 0.25 m · 0.5 · 0.013 = 731 kN/m
    t_u = 150e6 * 3e-3 * 0.25 * 0.5 * 0.013
    assert ext3.check.bar_force == pytest.approx(t_u)
    assert ext3.check.depth == pytest.approx((weight + t_u) / (0.85 * f_d * 1e3))
    assert ext3.check.depth > 0.25 and ext3.dropped and ext3.model_pivot == "edge"
    assert "no rocking mechanism" in (ext3.reason or "")
    # CFRP 1 ‰: x = (20.25 + 243.75)/1637 = 0.161 m: inside B/2 = 0.125, outside B
    assert cen1.check.depth == pytest.approx((weight + t_u / 3) / (0.85 * f_d * 1e3))
    assert cen1.dropped and "inside the compressed zone" in (cen1.reason or "")
    assert not ext1.dropped and ext1.model_pivot == "crushing"
    assert not gfrp.dropped
    # the record of results.json: every field a JSON value, the verdict in one line
    rec = asdict(ext1.result())
    assert rec["pivot_shift"] == pytest.approx(ext1.check.depth / 2)
    assert rec["dropped"] is False and "\n" not in rec["reason"]
    assert asdict(inp.masonry_strength)["f_d"] == pytest.approx(f_d)


def test_edge_rule_drops_what_the_paper_would_keep() -> None:
    checks = pivot_checks(inputs("edge"))
    assert not checks[0].dropped  # unreinforced x/B = 0.05
    assert all(c.model_pivot == "edge" for c in checks)
    assert [c.dropped for c in checks[1:]] == [True, True, True, True]  # GFRP 0.5 ‰: x/B = 0.155


def test_cache_key_follows_the_pivot_depth() -> None:
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


@pytest.mark.parametrize("pivot", ["edge", "crushing"])
@pytest.mark.parametrize("position", ["centred", "external"])
def test_largest_ratio_is_the_drop_rules_boundary(pivot: str, position: str) -> None:
    """By hand: ρ = (0.85·f_d·x_b − W)/(E·B·c·ε_u); just below it the option stays, just
    above it is dropped."""
    inp = inputs(pivot)
    f_d, weight = 2.6 / 1.35, 18.0 * 0.25 * 4.5
    bound = 0.1 * 0.25 if pivot == "edge" else (0.125 if position == "centred" else 0.25)
    expected = (0.85 * f_d * 1e3 * bound - weight) / (46e6 * 1e-3 * 0.25 * 0.5 * 0.015)
    rho = largest_ratio(inp, GFRP, position)  # type: ignore[arg-type]
    assert rho == pytest.approx(expected)
    for factor, dropped in ((0.99, False), (1.01, True)):
        option = Option("x", GFRP, position, factor * rho)  # type: ignore[arg-type]
        assert pivot_checks(replace(inp, options=(option,)))[1].dropped == dropped
