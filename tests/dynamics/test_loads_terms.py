"""The constants of the equation of motion with loads (dynamics/loads.py, docs/model.md §12)
against the independent statics of tests/dynamics/loads_reference.py (forces at points,
moments about the turned pivot, inertia summed over the wall and the carried masses)."""

from __future__ import annotations

import math

import pytest

from frp_assess.dynamics.loads import NO_LOADS, Loads, side_terms
from frp_assess.dynamics.wall import Wall
from frp_assess.rules.wall_loads import Thrust, TopLoad
from tests.dynamics.loads_reference import LoadedWall

B, H, W_UNIT = 0.4, 6.0, 18e3
TOP = ((10e3, 0.3, True), (4e3, 0.2, False))
THRUSTS = ((2e3, 5.5),)


def _loads() -> Loads:
    return Loads(
        top=tuple(TopLoad(p, d, c) for p, d, c in TOP),
        thrusts=tuple(Thrust(f, h) for f, h in THRUSTS),
    )


@pytest.mark.parametrize("side", [1, -1])
@pytest.mark.parametrize("theta", [0.0, 0.01, 0.05, 0.3])
@pytest.mark.parametrize("u", [0.0, -0.2, 0.35])
def test_bracket_equals_the_statics_of_the_turned_block(side: int, theta: float, u: float) -> None:
    wall = Wall(B, H, W_UNIT)
    sin_a, cos_a = math.sin(wall.alpha), math.cos(wall.alpha)
    t = side_terms(wall, _loads(), side, sin_a, cos_a)
    th = side * theta
    kernel = -t.p2 * ((t.a0 + u * t.a1) * math.cos(th) + (t.b0 + u * t.b1) * math.sin(th))
    ref = LoadedWall(B, H, W_UNIT, top=TOP, thrusts=THRUSTS)
    assert kernel == pytest.approx(ref.acceleration(th, side, u * 9.80665), rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("side", [1, -1])
def test_no_loads_are_the_walls_own_numbers_bit_for_bit(side: int) -> None:
    """Eq. 10's bracket: s·sin α, cos α, −cos α, s·sin α and p² = 3g/(4R), exactly."""
    wall = Wall(B, H, W_UNIT)
    sin_a, cos_a = math.sin(wall.alpha), math.cos(wall.alpha)
    t = side_terms(wall, NO_LOADS, side, sin_a, cos_a)
    assert t == (wall.p2, side * sin_a, cos_a, -cos_a, side * sin_a)
