"""results.json's ``model.restitution_ratio`` is the ratio the unreinforced wall's model applies:
Eqs. 13–14 at the slenderness about its pivot (docs/model.md §1.1).

Hand calculation: W = w·B·H [kN/m], f_d = f_m/FC, x = W/(0.85·f_d·1e3) [m],
tan α' = (B − x)/H; two-sided, energy reading: velocity ratio = 1 − 1.5·sin²α' (Housner 1963).
"""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from frp_assess.assess.results import applied_restitution_ratio
from frp_assess.dynamics import ModelOptions
from tests.assess.test_pivot import inputs


def housner(tan_alpha: float) -> float:
    return 1.0 - 1.5 * math.sin(math.atan(tan_alpha)) ** 2


@pytest.mark.parametrize("pivot", ["edge", "crushing"])
def test_restitution_ratio_is_at_the_walls_slenderness(pivot: str) -> None:
    """The corners strike in both models (docs/model.md §1.1): Eq. 13 at tan α = B/H, even
    where the base reaction moves the tipping angle to α_x."""
    base = inputs(pivot, mechanism="two-sided", compressive_strength=0.5)
    b, h = 0.25, 4.5  # the façade of tests/assess/test_pivot.py
    assert applied_restitution_ratio(base) == pytest.approx(housner(b / h), rel=1e-12)


def test_a_given_coefficient_is_reported_as_is() -> None:
    base = inputs("crushing", mechanism="two-sided")
    given = replace(base, model=ModelOptions(restitution=0.8, pivot="crushing"))
    assert applied_restitution_ratio(given) == 0.8
