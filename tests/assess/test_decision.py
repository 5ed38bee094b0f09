"""The one decision rule (frp_assess.assess.decision) on hand-made cases.

References: the rule of docs/results-json.md ("The decision") written out by hand, and
Circolare 2019 §C8.7.1.2.1.9 (d0 never exceeded in any record, mean peak ≤ d_SLV / d_SLC).
Every number below is computed in the docstrings.
"""

from __future__ import annotations

import math

import pytest

from frp_assess.assess.decision import (
    IDA_CHECK,
    PIVOT_CHECK,
    TH_SLC,
    TH_SLV,
    Evidence,
    decide,
    leave_one_out,
    time_history_deciding_check,
    verdict,
)

D0, D_SLV, D_SLC = 0.125, 0.050, 0.075  # [m]: d0 = B/2 of a 0.25 m wall, 0.4·d0, 0.6·d0
QUIET = (0.02,) * 7  # [m]: mean 20 mm ≤ 50 mm, no record beyond d0


def ev(
    name: str,
    cost: float,
    a_dyn: float | tuple[float, ...],
    peaks: tuple[float, ...] | None = QUIET,
    *,
    censored: tuple[bool, ...] = (False,) * 7,
    dropped: bool = False,
    unreinforced: bool = False,
) -> Evidence:
    """A case with 7 records; demand FC·a_g·S = 0.3 g, target 1."""
    values = a_dyn if isinstance(a_dyn, tuple) else (a_dyn,) * 7
    return Evidence(
        name=name,
        cost=cost,
        mass=cost / 10.0,
        a_dyn=values,
        censored=censored,
        demand=0.3,
        target=1.0,
        peaks=peaks,
        d0=D0,
        d_slv=D_SLV,
        d_slc=D_SLC,
        dropped=dropped,
        unreinforced=unreinforced,
    )


def test_capacity_above_the_target_but_d0_exceeded_is_not_recommended():
    """Option A: a_dyn 0.6 g → capacity/demand 0.6/0.3 = 2 ≥ 1, but one record's peak 0.13 m
    > d0 = 0.125 m: the time-history check fails (margin d0/0.13 = 0.9615), A is not
    recommended although it is the cheapest.  B (dearer, quiet records, 0.33 g → 1.1) is."""
    a = ev("A", 100.0, 0.6, (0.02,) * 6 + (0.13,))
    b = ev("B", 200.0, 0.33)
    d = decide([ev("URM", 0.0, 0.2, unreinforced=True), a, b])
    va = d.verdicts[1]
    assert va.checks[0].name == IDA_CHECK and va.checks[0].passed
    assert va.checks[0].margin == pytest.approx(2.0)
    assert not va.passes and va.governing_check == TH_SLV
    # mean peak = (6·0.02 + 0.13)/7 = 0.035714 m: d_SLV/mean = 1.4 > d0/max = 0.961538
    assert va.governing_margin == pytest.approx(0.125 / 0.13)
    assert d.recommended == 2 and d.closest is None
    assert d.order == (2, 1)  # the passing one first, then the others by margin
    assert d.verdicts[2].governing_margin == pytest.approx(1.1)  # 0.33/0.3, the IDA governs


def test_the_cheapest_passing_option_is_recommended():
    """Three options pass (a_dyn 0.45 g → 1.5); costs 300, 150, 150 with masses 30, 15, 15:
    the cheapest, then the lightest, then file order: index 2 first."""
    cases = [ev("URM", 0.0, 0.2, unreinforced=True)]
    cases += [ev("A", 300.0, 0.45), ev("B", 150.0, 0.45), ev("C", 150.0, 0.45)]
    d = decide(cases)
    assert d.recommended == 2 and d.order == (2, 3, 1)


def test_mean_peak_above_d_slv_fails_and_d_slc_is_looser():
    """Peaks 0.06 m ×7: no record beyond d0, mean 0.06 > d_SLV = 0.05 (margin 0.8333) but
    ≤ d_SLC = 0.075 (margin min(0.075/0.06, 0.125/0.06) = 1.25): SLV fails, SLC passes."""
    v = verdict(ev("A", 1.0, 0.6, (0.06,) * 7))
    by = {c.name: c for c in v.checks}
    assert not by[TH_SLV].passed and by[TH_SLV].margin == pytest.approx(0.05 / 0.06)
    assert by[TH_SLC].passed and by[TH_SLC].margin == pytest.approx(1.25)
    assert not v.passes and v.governing_check == TH_SLV
    assert "0 of 7 records exceed d0 = 125 mm" in by[TH_SLV].detail


def test_a_fall_gives_margin_zero_and_a_wall_at_rest_an_unbounded_margin():
    fell = time_history_deciding_check((0.01, math.inf, 0.01), D0, D_SLV, TH_SLV)
    assert fell.margin == 0.0 and not fell.passed and "falls under 1 of 3" in fell.detail
    rest = time_history_deciding_check((0.0, 0.0), D0, D_SLV, TH_SLV)
    assert rest.margin is None and rest.passed


def test_lower_bounds_pass_only_at_their_bound_and_rank_as_lower_bounds():
    """No collapse in 7/7 records up to C_max: a_dyn are lower bounds.  0.3228 g → ≥ 1.076
    passes (the bound itself reaches the target).  0.27 g → ≥ 0.9 does not pass (the true
    value is unknown above 0.9).  Among the failing ones a bound ≥ 0.9 ranks ahead of an
    exact 0.9 (it is at least as good) and behind an exact 0.95."""
    every = (True,) * 7
    strong = ev("LB", 500.0, 0.3228, censored=every)
    v = verdict(strong)
    assert v.passes and v.checks[0].lower_bound and v.governing_check == IDA_CHECK
    assert v.checks[0].detail.startswith("design a_dyn/(FC·a_g·S) = ≥ 1.08")
    weak_bound = ev("LB2", 100.0, 0.27, censored=every)
    exact_same = ev("E", 50.0, 0.27)
    exact_more = ev("E2", 900.0, 0.285)
    d = decide([ev("URM", 0.0, 0.1, unreinforced=True), exact_same, weak_bound, exact_more])
    assert not any(x.passes for x in d.verdicts)
    assert d.verdicts[2].governing_lower_bound
    assert d.order == (3, 2, 1)  # 0.95, then ≥ 0.9 ahead of the exact 0.9 (cheaper)
    assert d.recommended is None and d.closest == 3


def test_one_censored_record_makes_the_mean_a_lower_bound():
    """a_dyn (0.3, …, 0.3, bound 0.6) over 7: mean 0.342857 g → ≥ 1.142857."""
    a = ev("A", 1.0, (0.3,) * 6 + (0.6,), censored=(False,) * 6 + (True,))
    ida = verdict(a).checks[0]
    assert ida.lower_bound and ida.margin == pytest.approx((1.8 + 0.6) / 7 / 0.3)


def test_a_dropped_option_never_passes_and_gets_no_rank():
    """The strongest and cheapest option fails the pivot check: no rank, not recommended."""
    d = decide(
        [
            ev("URM", 0.0, 0.2, unreinforced=True),
            ev("A", 100.0, 0.45),
            ev("X", 1.0, 3.0, dropped=True),
        ]
    )
    vx = d.verdicts[2]
    assert not vx.passes and vx.governing_check == PIVOT_CHECK and vx.governing_margin == 0.0
    assert d.order == (1,) and d.recommended == 1


def test_none_passes_names_the_closest():
    """Margins: A 0.8 (IDA 0.24/0.3), B min(1.5, 0.125/0.14 = 0.8929) = 0.8929: B closest."""
    a = ev("A", 10.0, 0.24)
    b = ev("B", 20.0, 0.45, (0.02,) * 6 + (0.14,))
    d = decide([ev("URM", 0.0, 0.1, unreinforced=True), a, b])
    assert d.recommended is None and d.closest == 2 and d.order == (2, 1)


def test_when_a_record_falls_everywhere_the_closest_is_the_strongest_not_the_cheapest():
    """Every option's time history SLV has a record beyond d0 (peak inf: it fell), so each
    governing margin is 0 and ties. Closest to passing means the largest IDA margin:
    A (cheap) a_dyn 0.24 g → 0.24/0.3 = 0.8, B 0.27 g → 0.9, C (dearest) 0.285 g → 0.95.
    The rule before issue 39 broke the tie by cost and named A, the weakest."""
    fell = (0.02,) * 6 + (math.inf,)
    a = ev("A", 10.0, 0.24, fell)
    b = ev("B", 20.0, 0.27, fell)
    c = ev("C", 30.0, 0.285, fell)
    d = decide([ev("URM", 0.0, 0.1, unreinforced=True), a, b, c])
    assert all(d.verdicts[i].governing_margin == 0.0 for i in (1, 2, 3))
    assert d.recommended is None and d.closest == 3 and d.order == (3, 2, 1)


def test_the_unreinforced_wall_is_decided_but_never_recommended():
    d = decide([ev("URM", 0.0, 0.45, unreinforced=True), ev("A", 10.0, 0.45)])
    assert d.verdicts[0].passes and d.recommended == 1 and 0 not in d.order


def test_leave_one_out_finds_a_recommendation_carried_by_one_record():
    """A passes with a mean of 0.3 g·(6·0.98 + 1.12)/7 = 0.3 g → exactly 1.0; without the
    strong record 7 its mean is 0.294 g → 0.98 and B (dearer, 0.36 g → 1.2) takes over.
    Without any other record A's mean rises: it stays."""
    a = ev("A", 10.0, (0.294,) * 6 + (0.336,))
    b = ev("B", 20.0, 0.36)
    cases = [ev("URM", 0.0, 0.1, unreinforced=True), a, b]
    assert decide(cases).recommended == 1
    assert leave_one_out(cases) == [1, 1, 1, 1, 1, 1, 2]
