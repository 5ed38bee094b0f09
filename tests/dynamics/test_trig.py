"""The kernel's sin and cos of the rotation (frp_assess/dynamics/kernel/trig.py) against the
C library's (Python's math.sin/math.cos): within one unit in the last place over the range
the series cover, the library's own values beyond it.

The reference is independent: math.sin/math.cos are the platform's libm, correctly rounded
to within an ulp; the kernel's series are the Maclaurin series of sin and cos
(Abramowitz & Stegun, Handbook of Mathematical Functions, 4.3.65–66) truncated where
docs/model.md §4.2 says.
"""

from __future__ import annotations

import math

import numpy as np

from frp_assess.dynamics.kernel.trig import SERIES_REACH, sin_cos


def _points() -> np.ndarray:
    """Angles [rad] over the series' range: evenly spaced, logarithmically down to the
    smallest normal numbers (relative accuracy near 0), both signs, and the range's ends."""
    even = np.linspace(-SERIES_REACH, SERIES_REACH, 100_001)
    tiny = np.geomspace(1e-300, SERIES_REACH, 3001)
    ends = np.array([SERIES_REACH, np.nextafter(SERIES_REACH, 0.0), 0.0, -0.0])
    return np.concatenate([even, tiny, -tiny, ends, -ends])


def test_series_within_one_ulp_of_the_library() -> None:
    """|sin − math.sin| ≤ 1 ulp and |cos − math.cos| ≤ 1 ulp for |x| ≤ SERIES_REACH."""
    worst_s = worst_c = 0.0
    for x in _points():
        s, c = sin_cos(float(x))
        rs, rc = math.sin(x), math.cos(x)
        if rs != 0.0:
            worst_s = max(worst_s, abs(s - rs) / math.ulp(rs))
        else:
            assert s == 0.0
        worst_c = max(worst_c, abs(c - rc) / math.ulp(rc))
    assert worst_s <= 1.0
    assert worst_c <= 1.0


def test_odd_and_even() -> None:
    """sin(−x) = −sin x and cos(−x) = cos x exactly (the series are odd and even)."""
    for x in np.linspace(0.0, SERIES_REACH, 1001):
        s, c = sin_cos(float(x))
        sm, cm = sin_cos(float(-x))
        assert sm == -s
        assert cm == c


def test_beyond_the_series_the_library() -> None:
    """Outside the series' range (a wall on its way down, up to π/2 and past it) the values
    are the library's, bit for bit; NaN stays NaN."""
    for x in np.concatenate([np.linspace(SERIES_REACH * 1.0000001, 4.0, 2001), [-1.0, -3.0]]):
        assert sin_cos(float(x)) == (math.sin(x), math.cos(x))
    s, c = sin_cos(math.nan)
    assert math.isnan(s) and math.isnan(c)
