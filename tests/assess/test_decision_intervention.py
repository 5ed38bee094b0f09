"""The category of the intervention in the decision (frp_assess.assess.decision): the same
options judged as a local intervention, an improvement and an upgrade (NTC 2018 §8.4).

References: NTC 2018 §8.4.1-§8.4.3 read by hand (tests/rules/test_intervention.py quotes
§8.4.2) and the rule of docs/results-json.md ("The decision").  Every case has 7 records,
demand FC·a_g·S = 0.3 g and the IDA's target 1, so the IDA's ζ_E = a_dyn/0.3: a_dyn
0.135 g → ζ_E 0.45, 0.156 → 0.52, 0.168 → 0.56, 0.174 → 0.58, 0.285 → 0.95, 0.36 → 1.2.
The time-history peaks 20 mm ×7 give ζ_E = min(d_SLV/mean, d0/max) = min(50/20, 125/20)
= 2.5 at SLV and min(75/20, 125/20) = 3.75 at SLC: the IDA governs every case.
"""

from __future__ import annotations

import pytest

from frp_assess.assess.decision import (
    DECISION_RULE,
    IDA_CHECK,
    TH_SLV,
    InterventionCategory,
    decide,
    decision_rule,
    leave_one_out,
)
from tests.assess.test_decision import ev

URM = ev("URM", 0.0, 0.135, unreinforced=True)  # ζ_E 0.45
A = ev("A", 100.0, 0.156)  # 0.52
B = ev("B", 200.0, 0.168)  # 0.56
C = ev("C", 300.0, 0.174)  # 0.58
D = ev("D", 400.0, 0.285)  # 0.95
CASES = [URM, A, B, C, D]


def passing(intervention: InterventionCategory) -> list[str]:
    d = decide(CASES, intervention)
    return [c.name for c, v in zip(CASES, d.verdicts, strict=True) if v.passes]


def test_improvement_of_class_ii_needs_the_unreinforced_zeta_plus_one_tenth():
    """§8.4.2, class II: 0.45 + 0.1 = 0.55: A (0.52) fails, B (0.56), C, D pass; B is the
    cheapest passing: recommended.  A's margin 0.52/0.55 = 0.94545."""
    imp = InterventionCategory("improvement", "II")
    assert passing(imp) == ["B", "C", "D"]
    d = decide(CASES, imp)
    assert d.recommended == 2
    assert d.verdicts[1].governing_margin == pytest.approx(0.52 / 0.55)
    assert d.verdicts[1].checks[0].detail.endswith("against the target 0.55")


def test_improvement_of_class_iv_needs_six_tenths():
    """§8.4.2, class IV (and a class III school): ζ_E ≥ 0.6: A, B and C (0.58) fail, D
    (0.95) passes and is recommended; a class III building not used as a school takes the
    +0.1 rule again (B, C, D)."""
    assert passing(InterventionCategory("improvement", "IV")) == ["D"]
    assert passing(InterventionCategory("improvement", "III", school=True)) == ["D"]
    assert passing(InterventionCategory("improvement", "III")) == ["B", "C", "D"]
    assert decide(CASES, InterventionCategory("improvement", "IV")).recommended == 4


def test_upgrade_needs_one_and_is_the_default():
    """§8.4.3: ζ_E ≥ 1: D (0.95) fails like the others: none is recommended, the closest is
    D (largest margin 0.95).  The default is the upgrade: the same decision."""
    up = decide(CASES, InterventionCategory("upgrade"))
    assert passing(InterventionCategory("upgrade")) == []
    assert up.recommended is None and up.closest == 4
    assert decide(CASES) == up


def test_local_needs_the_governing_check_to_rise_and_no_check_worse():
    """§8.4.1: every option raises the IDA's ζ_E above 0.45 and keeps the time histories
    (the same peaks): all pass; A, the cheapest, is recommended.  An option E with ζ_E 0.50
    whose time history at SLV gets worse (peaks 30 mm: ζ_E 50/30 = 1.667 < 2.5, but ≥ 1)
    still passes: a check with margin may lose part of it.  F (0.50) with peaks 60 mm
    (ζ_E 50/60 = 0.833 < 1 and < 2.5) fails: it made the SLV check worse and failing."""
    assert passing(InterventionCategory("local")) == ["A", "B", "C", "D"]
    assert decide(CASES, InterventionCategory("local")).recommended == 1
    e = ev("E", 50.0, 0.15, (0.03,) * 7)
    f = ev("F", 60.0, 0.15, (0.06,) * 7)
    d = decide([URM, e, f], InterventionCategory("local"))
    assert d.verdicts[1].passes
    vf = d.verdicts[2]
    assert not vf.passes and vf.governing_check == TH_SLV
    assert vf.governing_margin == pytest.approx((0.05 / 0.06) / 1.0)


def test_local_fails_an_option_that_does_not_raise_the_governing_check():
    """§8.4.1: an option with the unreinforced ζ_E 0.45 itself (a_dyn 0.135) does not
    improve the mechanism: it fails (margin 1.0, but it must exceed)."""
    same = ev("same", 10.0, 0.135)
    d = decide([URM, same], InterventionCategory("local"))
    ida = d.verdicts[1].checks[0]
    assert ida.name == IDA_CHECK and not ida.passed and ida.margin == pytest.approx(1.0)
    assert "to be exceeded" in ida.detail


def test_the_unreinforced_wall_is_judged_by_the_assessment():
    """In every category the wall as it is passes only at ζ_E ≥ 1 (0.45: fails), so a
    retrofit stays required whatever the category."""
    for cat in ("local", "improvement", "upgrade"):
        d = decide(CASES, InterventionCategory(cat, "II"))  # type: ignore[arg-type]
        assert not d.verdicts[0].passes


def test_leave_one_out_takes_the_requirement_again():
    """Leaving a record out of the improvement (class II): the unreinforced ζ_E is
    recomputed from the 6 records left.  With the unreinforced a_dyn 0.135 g on six records
    and 0.195 g on the seventh, its mean is (6·0.135 + 0.195)/7 = 0.14357 g, ζ_E 0.47857,
    requirement 0.57857: B (0.56) fails, C (0.58) passes.  Without the seventh record the
    unreinforced ζ_E is 0.45, requirement 0.55: B passes and is recommended.  Without one
    of the others: (5·0.135 + 0.195)/6 = 0.145 g, ζ_E 0.48333, requirement 0.58333 > 0.58:
    nothing passes."""
    urm = ev("URM", 0.0, (0.135,) * 6 + (0.195,), unreinforced=True)
    imp = InterventionCategory("improvement", "II")
    d = decide([urm, B, C], imp)
    assert [v.passes for v in d.verdicts[1:]] == [False, True] and d.recommended == 2
    picks = leave_one_out([urm, B, C], imp)
    assert picks[6] == 1 and picks[:6] == [None] * 6


def test_the_rule_in_words_names_the_category():
    """The upgrade's words are today's; the others name their clause and what they need."""
    assert decision_rule(InterventionCategory(), 1.0) == DECISION_RULE.format(target=1.0)
    assert "NTC 2018 §8.4.1" in decision_rule(InterventionCategory("local"), 1.0)
    words = decision_rule(InterventionCategory("improvement", "IV"), 1.0)
    assert "≥ 0.6" in words and "§8.4.2" in words and "class IV" in words
    assert "+ 0.1" in decision_rule(InterventionCategory("improvement", "II"), 1.0)
