"""a* = α·g/(e*·FC), Circolare 2019 §C8.7.1.2.1.3 eq. C8.7.1.3, checked by hand calculations
with the confidence factors of Tab. C8.5.IV typed from the table (LC1 1.35, LC2 1.20, LC3 1.00)
and g = 9.80665 m/s² typed from ISO 80000-3."""

from __future__ import annotations

import pytest

from frp_assess.rules.constants import G
from frp_assess.rules.kinematic import a_star
from frp_assess.rules.masonry import confidence_factor


def test_standard_gravity() -> None:
    assert G == 9.80665


@pytest.mark.parametrize("level,fc", [("LC1", 1.35), ("LC2", 1.20), ("LC3", 1.00)])
def test_a0_star_of_the_simple_overturning(level: str, fc: float) -> None:
    """B = 0.3 m, H = 3 m: α0 = B/H = 0.1, e* = 1: a0* = 0.1·9.80665/FC [m/s²], 0.1/FC [g]."""
    assert confidence_factor(level) == fc
    assert a_star(0.1, 1.0, fc) == pytest.approx(0.980665 / fc, rel=1e-15)
    assert a_star(0.1, 1.0, fc, g=1.0) == pytest.approx(0.1 / fc, rel=1e-15)


def test_a_star_with_a_participating_mass_fraction() -> None:
    """α = 0.2, e* = 0.8, FC = 1.2: a* = 0.2·9.80665/(0.8·1.2) = 2.04305208… m/s²."""
    assert a_star(0.2, 0.8, 1.2) == pytest.approx(2.0430520833333, rel=1e-12)
