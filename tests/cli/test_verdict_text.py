"""The decision in words (frp_assess.numbers): lower bounds read "≥", the verdict names the
governing check and margin, and nothing is called recommended that fails a deciding check.

Reference: the report's fixture (tests/report/data/results.json) with its fields set by hand.
"""

from __future__ import annotations

from dataclasses import replace

from frp_assess.numbers import fmt_capacity, recommendation_text, verdict_text
from tests.report.test_report import raw, typed


def test_a_lower_bound_reads_as_one_everywhere():
    """capacity/demand 1.076 from 7 records without collapse: "≥ 1.08" (the bound), and the
    verdict's margin "≥ 1.08" too."""
    case = replace(
        typed(raw()).cases[1],
        capacity_demand=1.076,
        lower_bound=True,
        passes=True,
        governing_check="IDA capacity/demand",
        governing_margin=1.076,
        governing_lower_bound=True,
    )
    assert fmt_capacity(case, 1.0) == "≥ 1.08"
    assert verdict_text(case) == "passes: IDA capacity/demand ≥ 1.08"
    exact = replace(case, lower_bound=False, governing_lower_bound=False)
    assert fmt_capacity(exact, 1.0) == "1.08" and verdict_text(exact).endswith(" 1.08")


def test_a_fall_is_said_and_an_old_file_has_no_verdict():
    case = replace(
        typed(raw()).cases[1],
        passes=False,
        governing_check="time history SLV",
        governing_margin=0.0,
    )
    assert verdict_text(case) == "fails: time history SLV (a record makes the wall fall)"
    assert verdict_text(replace(case, passes=None)) == "—"


def test_none_passes_names_the_closest_and_recommends_nothing():
    r = typed(raw())
    urm, *opts = r.cases
    urm = replace(urm, passes=False, meets_target=False)
    closest = replace(
        opts[0], passes=False, governing_check="time history SLV", governing_margin=0.65
    )
    r = replace(r, cases=(urm, closest, *opts[1:]), recommended=None, closest=closest.name)
    text = recommendation_text(r)
    assert text == (
        "none of the options passes every deciding check; the closest is "
        f"{closest.name} (time history SLV 0.65)"
    )
