"""The rocking block's geometry (docs/model.md §1, paper Eqs. 2–5): tan α = B/H,
R = ½·√(B² + H²); a rocking wall has finite sizes > 0 and B < H."""

from __future__ import annotations

import math

import pytest

from frp_assess.rules.geometry import (
    half_diagonal,
    is_rocking_block,
    size_problem,
    slenderness,
    slenderness_problem,
    thickness_of,
)


def test_slenderness_and_half_diagonal_by_hand() -> None:
    # B = 0.3, H = 0.4 (a 3-4-5 triangle): α = atan(0.75) = 0.643501 rad, R = 0.25 m
    assert slenderness(0.3, 0.4) == pytest.approx(0.643501, abs=1e-6)
    assert half_diagonal(0.3, 0.4) == pytest.approx(0.25)
    # the paper's wall: H = 3 m, α = 7.5°: B = 3·tan 7.5° = 0.394957 m
    assert thickness_of(3.0, math.radians(7.5)) == pytest.approx(0.394957, abs=1e-6)


@pytest.mark.parametrize(
    "b,h,ok",
    [(0.4, 3.0, True), (3.0, 3.0, False), (3.5, 3.0, False), (0.0, 3.0, False),
     (-0.1, 3.0, False), (math.nan, 3.0, False), (0.4, math.inf, False)],
)  # fmt: skip
def test_a_rocking_block(b: float, h: float, ok: bool) -> None:
    assert is_rocking_block(b, h) is ok


def test_problems_are_one_line() -> None:
    assert size_problem(0.4) is None
    assert size_problem(-1.0, "thickness") == "expected thickness > 0 m, found -1.0"
    assert slenderness_problem(0.4, 3.0) is None
    line = slenderness_problem(3.5, 3.0)
    assert line is not None and "B = 3.5 m >= H = 3 m" in line and "\n" not in line
