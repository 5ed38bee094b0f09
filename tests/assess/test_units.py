"""FRP quantities, and the code kinematic check (hand calculations).

Kinematic check source: Circolare 2019 §C8.7.1 (a0* = α0·g/(e*·FC), ground-level check
a0* ≥ a_g·S/q, q = 2) and Tab. C8.5.IV (FC = 1.35/1.20/1.00); α0 = B/H for the simple
overturning of a monolithic wall.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from frp_assess.assess.code_check import simple_overturning_check
from frp_assess.assess.inputs import CostSettings, Material
from frp_assess.assess.quantities import frp_quantity
from frp_assess.numbers import recommendation_text
from frp_assess.results.json_io import from_json
from frp_assess.results.model import AssessmentResult, Fragility

GFRP = Material("GFRP", 46.0, 0.015, 2000.0, 8.0)


@pytest.mark.parametrize("position,layers", [("centred", 1), ("external", 2)])
def test_quantities(position, layers):
    q = frp_quantity(0.4, 3.0, 6.0, GFRP, position, 2.0, CostSettings("EUR", 150.0))
    area = 2e-3 * 0.4 * layers  # m² per metre of wall
    assert q.mass_per_m == pytest.approx(area * 3.0 * 2000.0)
    assert q.mass == pytest.approx(q.mass_per_m * 6.0)
    assert q.cost == pytest.approx(q.mass * 8.0 + 150.0 * 6.0 * layers)


def test_kinematic_check_by_hand():
    c = simple_overturning_check(0.4, 3.0, 0.30, "LC1", 2.0)
    assert c.alpha0 == pytest.approx(0.4 / 3.0)
    assert c.a0_star == pytest.approx(0.4 / 3.0 / 1.35)
    assert c.demand == pytest.approx(0.15)
    assert c.passed is False  # 0.0988 g < 0.15 g
    assert simple_overturning_check(0.4, 3.0, 0.15, "LC3").passed is True
    with pytest.raises(ValueError):
        simple_overturning_check(0.4, 3.0, 0.3, "LC4")


def _fixture_results() -> AssessmentResult:
    """The report's results fixture (typed), to vary one field at a time."""
    data = Path(__file__).resolve().parents[1] / "report" / "data" / "results.json"
    return from_json(data.read_text(encoding="utf-8"))


def test_recommendation_says_when_no_retrofit_is_needed():
    """The printed recommendation does not present an option as required when the unreinforced
    wall (case 0) already passes; it names the option only as extra margin.  (The fixture's
    cases are undecided, ``passes`` None: the IDA's meets_target stands in for the verdict.)"""
    base = _fixture_results()

    def results(urm_ok: bool, rec: str | None) -> AssessmentResult:
        urm = replace(base.cases[0], meets_target=urm_ok)
        return replace(base, recommended=rec, cases=(urm, *base.cases[1:]))

    assert recommendation_text(results(False, "GFRP external 1‰")) == "GFRP external 1‰"
    assert (
        recommendation_text(results(False, None))
        == "none of the options passes every deciding check"
    )
    ok = recommendation_text(results(True, "GFRP centred 1‰"))
    assert ok.startswith("no retrofit needed") and "extra margin: GFRP centred 1‰" in ok
    assert "extra margin" not in recommendation_text(results(True, None))


def test_no_retrofit_needed_says_what_contradicts_it():
    """Issue 15 §3: never "no retrofit needed" while the code check of the same wall fails or
    the margin is within the scatter of the records, without saying so."""
    base = _fixture_results()

    def results(passed: bool, cd: float, cov: float, p: float | None) -> AssessmentResult:
        sc = base.cases[0].scatter
        fragility = None if p is None else Fragility(0.3, 0.2, "mle", p)
        urm = replace(
            base.cases[0],
            meets_target=True,
            capacity_demand=cd,
            scatter=replace(sc, cov=cov, fragility=fragility),
        )
        return replace(
            base,
            recommended=None,
            cases=(urm, *base.cases[1:]),
            code_check=replace(base.code_check, passed=passed),
            model=replace(base.model, target=1.0),
        )

    assert recommendation_text(results(True, 2.0, 0.1, 1e-6)).endswith(
        "passes every deciding check"
    )
    failing = recommendation_text(results(False, 2.0, 0.1, 1e-6))
    assert "kinematic check of Circolare 2019 §C8.7.1 is NOT satisfied" in failing
    assert "probability of collapse at the demand is 25%" in recommendation_text(
        results(True, 1.05, 0.1, 0.25)
    )
    assert "margin (5%) is within the scatter of the records (CoV 20%)" in recommendation_text(
        results(True, 1.05, 0.2, None)
    )
