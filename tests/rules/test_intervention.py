"""The category of the intervention (frp_assess.rules.intervention) against NTC 2018 §8.4
read by hand.

§8.4.2 (improvement): "per le costruzioni di classe III ad uso scolastico e di classe IV il
valore di ζE, a seguito degli interventi di miglioramento, deve essere comunque non minore di
0,6, mentre per le rimanenti costruzioni di classe III e per quelle di classe II il valore di
ζE ... deve essere incrementato di un valore comunque non minore di 0,1".  §8.4.3 (upgrade,
cases a, b, d): ζE ≥ 1,0.  §8.4.1 (local): the safety of the part improves, nothing worse.
Every number below is worked out in the test's docstring.
"""

from __future__ import annotations

import pytest

from frp_assess.rules.intervention import (
    CATEGORIES,
    CATEGORY_CLAUSE,
    UPGRADE_ZETA,
    improvement_has_minimum,
    improvement_zeta,
    local_requirement,
    meets,
)


def test_improvement_of_class_ii_needs_the_as_is_value_plus_one_tenth():
    """Class II, ζ_E as is 0.45: it must reach 0.45 + 0.1 = 0.55; 0.52 fails, 0.56 passes,
    0.55 itself passes (not less than)."""
    need = improvement_zeta(0.45, "II", school=False)
    assert need == pytest.approx(0.55)
    assert not meets(0.52, need)
    assert meets(0.56, need)
    assert meets(0.55, need)


def test_improvement_of_class_iv_and_of_a_class_iii_school_needs_six_tenths():
    """Class IV, ζ_E as is 0.45: it must reach 0.6 whatever the as-is value: 0.58 fails
    (although 0.58 ≥ 0.45 + 0.1), 0.61 passes.  A class III school the same; a class III
    construction not used as a school takes +0.1: 0.58 ≥ 0.55 passes."""
    assert improvement_zeta(0.45, "IV", school=False) == 0.6
    assert improvement_zeta(0.45, "III", school=True) == 0.6
    assert not meets(0.58, improvement_zeta(0.45, "IV", school=False))
    assert meets(0.61, improvement_zeta(0.45, "IV", school=False))
    assert meets(0.58, improvement_zeta(0.45, "III", school=False))
    # as is 0.55: the 0.6 binds class IV at 0.6, class II at 0.65
    assert not meets(0.62, improvement_zeta(0.55, "II", school=False))
    assert meets(0.62, improvement_zeta(0.55, "IV", school=False))


def test_which_constructions_the_six_tenths_binds():
    """§8.4.2: class IV always, class III only as a school; classes I and II never (a school
    flag on class II changes nothing: the clause names class III schools)."""
    assert improvement_has_minimum("IV", school=False)
    assert improvement_has_minimum("III", school=True)
    assert not improvement_has_minimum("III", school=False)
    assert not improvement_has_minimum("II", school=True)
    assert not improvement_has_minimum("I", school=False)


def test_upgrade_needs_one():
    """§8.4.3 cases a, b, d: ζ_E ≥ 1.0: 0.95 fails, 1.0 passes."""
    assert UPGRADE_ZETA == 1.0
    assert not meets(0.95, UPGRADE_ZETA)
    assert meets(1.0, UPGRADE_ZETA)


def test_local_no_check_worse_and_the_governing_one_better():
    """§8.4.1, the unreinforced mechanism's ζ_E 0.40 (its governing check), another check
    at 0.70 and a third at 1.30: the governing check must exceed 0.40 (0.40 itself fails,
    0.41 passes); the second must stay ≥ 0.70 (0.69 is worse: fails); the third, which passes
    the assessment, may lose margin down to 1 (1.0 passes, 0.99 fails)."""
    value, strict = local_requirement(0.40, 0.40)
    assert (value, strict) == (0.40, True)
    assert not meets(0.40, value, strict) and meets(0.41, value, strict)
    value, strict = local_requirement(0.70, 0.40)
    assert (value, strict) == (0.70, False)
    assert meets(0.70, value, strict) and not meets(0.69, value, strict)
    value, strict = local_requirement(1.30, 0.40)
    assert (value, strict) == (1.0, False)
    assert meets(1.0, value, strict) and not meets(0.99, value, strict)


def test_an_unbounded_zeta_meets_anything():
    """None is a check where nothing moved (ζ_E unbounded): it meets any requirement."""
    assert meets(None, 1.0) and meets(None, 0.6, strict=True)


def test_every_category_has_its_clause():
    assert CATEGORIES == ("local", "improvement", "upgrade")
    assert [CATEGORY_CLAUSE[c] for c in CATEGORIES] == [
        "NTC 2018 §8.4.1",
        "NTC 2018 §8.4.2",
        "NTC 2018 §8.4.3",
    ]
