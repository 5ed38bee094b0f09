"""Tie-rods as retrofit options (docs/model.md §12): their steel and cost by hand, their wall
model (the wall's loads with the tie added, the path every tie takes into the dynamics), the
static α₀ of the option against Circolare 2019 eq. C8.7.1.1 by hand, and the ranking of a
tie option with FRP bars by the decision's pure functions.

The wall (as tests/assess/test_loaded_checks.py): B = 0.4 m, H = 6 m, w = 18 kN/m³,
W = 18·0.4·6 = 43.2 kN/m, W·B/2 = 8.64 and W·H/2 = 129.6 kNm/m, the edge pivot (x₀ = 0); a
carried floor P = 10 kN/m at d = 0.3 m (P·d = 3.0, P·H = 60 kNm/m).  The tie: Ø20
(A_s = π·20²/4 = 314.159 mm²), S235, every i_t = 3 m, L_t = 8 m, at h_t = 5.5 m, anchorage
F_a = 40 kN per tie: F_y = 314.159e-6·235e6/3 = 24.609 kN/m > F_a/i_t = 40/3 = 13.333 kN/m
(brittle), so L_i = min(F_y, F_a/i_t)·h_t = 13.333·5.5 = 73.333 kNm/m.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from frp_assess.assess.decision import Evidence, decide
from frp_assess.assess.from_project import inputs_from_project
from frp_assess.assess.inputs import AssessmentInputs, TiePrices
from frp_assess.assess.kinematic_checks import linear_check
from frp_assess.assess.load_inputs import TieInput
from frp_assess.assess.loaded_overturning import loaded_alpha0
from frp_assess.assess.quantities import option_quantity, tie_quantity
from frp_assess.config.loader import load_project_text
from frp_assess.errors import InputError

PROJECT = """\
wall:
  thickness: 0.4
  height: 6.0
  length: 6.0
  unit_weight: 18
  mechanism: one-sided
  loads:
    top: [{name: floor, load: 10.0, distance: 0.3}]
seismic:
  spectrum: {type: preset, name: A2}
  records: {artificial: {count: 1, seed: 1, duration: 13.5, dt: 0.05}}
interventions:
  - {type: tie, height: 5.5, diameter: 20, spacing: 3.0, length: 8.0, anchorage: 40}
  - {material: GFRP, position: external, ratio: 1}
  - material: GFRP
    position: external
    ratio: 1
    tie: {height: 5.5, diameter: 20, spacing: 3.0, length: 8.0, anchorage: 40}
analysis: {pivot: edge}
costs: {tie_steel_per_kg: 2.5, tie_steel_per_metre: 1.0, tie_plate: 60, tie_installation: 300}
"""
A_S = math.pi * 20.0**2 / 4.0  # [mm²]


def _inputs(text: str = PROJECT) -> AssessmentInputs:
    loaded = load_project_text(text, "p.yaml", base_dir=Path("."))
    return inputs_from_project(loaded.project, loaded.base_dir, "p.yaml")


def test_a_ties_steel_and_cost_by_hand() -> None:
    """One tie every 3 m: ρ·A_s·L_t = 7850·314.159e-6·8 = 19.7292 kg; per metre of wall
    ÷ 3 = 6.5764 kg/m, over L = 6 m: 39.458 kg.  One tie costs its bar 19.7292·2.5 + 8·1.0,
    two plates 2·60 and its installation 300: 49.323 + 8 + 120 + 300 = 477.323; per metre
    ÷ 3 = 159.108, over 6 m: 954.646."""
    tie = TieInput("t", 5.5, A_S, 3.0, 8.0)
    q = tie_quantity(tie, TiePrices(2.5, 1.0, 60.0, 300.0), 6.0)
    mass_per_tie = 7850.0 * 314.1592653589793e-6 * 8.0
    assert mass_per_tie == pytest.approx(19.7292, abs=5e-5)
    assert q.mass_per_m == pytest.approx(mass_per_tie / 3.0, rel=1e-12)
    assert q.mass == pytest.approx(6.0 * mass_per_tie / 3.0, rel=1e-12)
    per_tie = mass_per_tie * 2.5 + 8.0 * 1.0 + 2 * 60.0 + 300.0
    assert per_tie == pytest.approx(477.323, abs=5e-4)
    assert q.cost_per_tie == pytest.approx(per_tie, rel=1e-12)
    assert q.cost_per_m == pytest.approx(per_tie / 3.0, rel=1e-12)
    assert q.cost == pytest.approx(954.646, abs=5e-4)
    free = tie_quantity(tie, TiePrices(), 6.0)
    assert (free.cost, free.mass) == (0.0, q.mass)
    assert not TiePrices().given and TiePrices(plate=1.0).given


def test_the_options_model_is_the_walls_with_the_tie_in_its_loads() -> None:
    """The tie option's model: no bars, the floor and the tie in its loads (k_t, F_y, F_a/i_t
    of rules/tie_rods.py); the bars+tie option: the bars option's bars and the same loads; the
    unreinforced wall and the bars option carry the floor alone."""
    inputs = _inputs()
    tie_only, bars, both = inputs.options
    assert (tie_only.kind, bars.kind, both.kind) == ("tie", "bars", "bars+tie")
    assert tie_only.material is None and tie_only.ratio == 0.0
    urm = inputs.model_for(None)
    assert urm.loads.ties == () and len(urm.loads.top) == 1
    assert inputs.model_for(bars).loads == urm.loads
    assert tie_only.tie is not None
    expected = tie_only.tie.tie()
    assert expected.yield_force == pytest.approx(A_S * 1e-6 * 235e6 / 3.0, rel=1e-12)
    assert expected.anchorage_force == pytest.approx(40e3 / 3.0, rel=1e-12)
    m_tie = inputs.model_for(tie_only)
    assert m_tie.loads.top == urm.loads.top and m_tie.loads.ties == (expected,)
    assert m_tie.K == urm.K == 0.0
    m_both = inputs.model_for(both)
    assert m_both.loads.ties == (expected,)
    assert m_both.rebars == inputs.model_for(bars).rebars and m_both.K > 0.0
    # the wall's own ties stay, the option's is added after them (at the same tie level: the
    # same height, steel and length, so the time histories sum them)
    with_catena = PROJECT.replace(
        "    top: [{name: floor, load: 10.0, distance: 0.3}]\n",
        "    top: [{name: floor, load: 10.0, distance: 0.3}]\n"
        "    ties: [{height: 5.5, diameter: 20, spacing: 4.0, length: 8.0, anchorage: 40}]\n",
    )
    loaded = _inputs(with_catena)
    ties = loaded.model_for(loaded.options[0]).loads.ties
    assert len(ties) == 2 and ties[1] == expected
    assert ties[0] == loaded.model_for(None).loads.ties[0]


def test_a_tie_option_at_another_level_than_the_walls_own_ties() -> None:
    """The time histories hold two tie levels (docs/model.md §12): an option's tie at 5.5 m
    on a wall whose own tie is at 5.8 m is a second level, both in the option's model; on a
    wall with ties at two other heights it is refused with one located line, not a
    traceback."""
    own = "    ties: [{height: 5.8, diameter: 16, spacing: 4.0, length: 8.0}]\n"
    floor = "    top: [{name: floor, load: 10.0, distance: 0.3}]\n"
    loaded = _inputs(PROJECT.replace(floor, floor + own))
    heights = [t.height for t in loaded.model_for(loaded.options[0]).loads.ties]
    assert heights == [5.8, 5.5]
    two = (
        "    ties: ["
        + ", ".join(f"{{height: {h}, diameter: 16, spacing: 4.0, length: 8.0}}" for h in (5.8, 4.0))
        + "]\n"
    )
    with pytest.raises(InputError, match=r"interventions\[0\].*at most 2 tie levels.*level 3"):
        _inputs(PROJECT.replace(floor, floor + two))


def test_static_alpha0_of_a_tie_option_by_hand() -> None:
    """Eq. C8.7.1.1 about the outer corner, the edge pivot: the wall with the floor
    α₀ = (8.64 + 3.0)/(129.6 + 60) = 11.64/189.6 = 0.0613924; the tie option adds
    L_i = min(F_y, F_a/i_t)·h_t = (40/3)·5.5 = 73.3333 kNm/m:
    α₀ = (11.64 + 73.3333)/189.6 = 0.448172.  The bars (unstressed at rest) leave it alone:
    the bars+tie option has the tie option's α₀."""
    inputs = _inputs()
    tie_only, bars, both = inputs.options
    l_i = 40.0 / 3.0 * 5.5
    assert l_i == pytest.approx(73.3333, abs=5e-5)
    hand_urm = (43.2 * 0.2 + 10.0 * 0.3) / (43.2 * 3.0 + 10.0 * 6.0)
    hand_tie = (43.2 * 0.2 + 10.0 * 0.3 + l_i) / (43.2 * 3.0 + 10.0 * 6.0)
    assert hand_tie == pytest.approx(0.448172, abs=5e-7)
    assert loaded_alpha0(inputs.model_for(None)) == pytest.approx(hand_urm, rel=1e-12)
    assert loaded_alpha0(inputs.model_for(bars)) == pytest.approx(hand_urm, rel=1e-12)
    for option in (tie_only, both):
        model = inputs.model_for(option)
        assert loaded_alpha0(model) == pytest.approx(hand_tie, rel=1e-12)
        # the linear check the report prints takes the same α₀
        assert linear_check(model, 0.2, "LC1", 2.0).alpha0 == pytest.approx(hand_tie, rel=1e-12)
        # where rocking starts (a_RM/g) the tie is unstretched: the wall's
        assert loaded_alpha0(model, with_ties=False) == pytest.approx(hand_urm, rel=1e-12)


def test_a_tie_alone_on_a_free_standing_wall_by_hand() -> None:
    """Without wall loads the tie option alone makes the model loaded: α₀ = (W·B/2 + L_i)
    / (W·H/2) = (8.64 + 73.3333)/129.6 = 0.632510 against B/H = 0.0667 for the wall."""
    text = PROJECT.replace("  loads:\n    top: [{name: floor, load: 10.0, distance: 0.3}]\n", "")
    inputs = _inputs(text)
    assert not inputs.loads
    model = inputs.model_for(inputs.options[0])
    assert model.loads and not inputs.model_for(None).loads
    hand = (43.2 * 0.2 + 40.0 / 3.0 * 5.5) / (43.2 * 3.0)
    assert hand == pytest.approx(0.632510, abs=5e-7)
    assert linear_check(model, 0.2, "LC1", 2.0).alpha0 == pytest.approx(hand, rel=1e-12)


def test_option_costs_bars_tie_and_both() -> None:
    """The bars of the bars+tie option cost what the bars option's do; a tie alone has no
    FRP; the ranking's cost is their sum (results' CaseResult.option_cost)."""
    inputs = _inputs()
    tie_only, bars, both = inputs.options
    assert option_quantity(inputs, tie_only).cost == 0.0
    assert option_quantity(inputs, both) == option_quantity(inputs, bars)
    assert option_quantity(inputs, bars).cost > 0.0


def _ev(name: str, cost: float, a_dyn: float, *, unreinforced: bool = False) -> Evidence:
    """7 records, demand FC·a_g·S = 0.3 g, target 1, quiet time histories (peaks 20 mm
    against d_SLV = 50 mm, d0 = 125 mm)."""
    return Evidence(
        name=name,
        cost=cost,
        mass=cost / 10.0,
        a_dyn=(a_dyn,) * 7,
        censored=(False,) * 7,
        demand=0.3,
        target=1.0,
        peaks=(0.02,) * 7,
        d0=0.125,
        d_slv=0.05,
        d_slc=0.075,
        unreinforced=unreinforced,
    )


def test_a_tie_option_is_ranked_with_the_bars_by_the_same_rule() -> None:
    """With the prices above, the tie alone costs 954.6 over the 6 m wall and the bars
    option c_b: passing, the cheaper first; the bars+tie option costs c_b + 954.6.  A tie
    option that does not pass ranks after every passing option by its margin."""
    inputs = _inputs()
    tie_only, bars, both = inputs.options
    assert tie_only.tie is not None
    c_tie = tie_quantity(tie_only.tie, inputs.costs.ties, inputs.length).cost
    c_bars = option_quantity(inputs, bars).cost
    assert c_tie == pytest.approx(954.646, abs=5e-4)
    urm = _ev("wall", 0.0, 0.25, unreinforced=True)  # 0.25/0.3 < 1: fails
    passing = [
        urm,
        _ev("tie", c_tie, 0.4),
        _ev("bars", c_bars, 0.5),
        _ev("both", c_bars + c_tie, 0.6),
    ]
    d = decide(passing)
    assert c_bars < c_tie  # GFRP 1 ‰ on both faces of this wall: about 460 EUR
    assert [passing[i].name for i in d.order] == ["bars", "tie", "both"]
    cheap_tie = [urm, _ev("tie", c_bars / 2.0, 0.4), *passing[2:]]
    assert [cheap_tie[i].name for i in decide(cheap_tie).order] == ["tie", "bars", "both"]
    failing_tie = [
        urm,
        _ev("tie", c_tie, 0.28),
        _ev("bars", c_bars, 0.5),
        _ev("both", c_bars + c_tie, 0.6),
    ]
    d = decide(failing_tie)
    assert [failing_tie[i].name for i in d.order] == ["bars", "both", "tie"]
    assert failing_tie[d.recommended or 0].name == "bars"
