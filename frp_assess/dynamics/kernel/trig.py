"""sin and cos of the rotation, for the right-hand side of Eq. 10 (docs/model.md §4.2).

The kernel evaluates sin θ and cos θ at every stage of every step (six per step), and with
one step per record sample they were a third of its time: the library calls cannot be
inlined, and the stages depend on one another, so their latency adds up.  While the wall
rocks |θ| ≤ α_x ≤ ~0.2 rad (the corners of the paper's walls are at 5–10°), where the
Maclaurin series converge fast: truncated after θ¹¹ (sin) and θ¹² (cos), their remainders
are below 3·10⁻¹⁸ for |θ| ≤ SERIES_REACH, far below one unit in the last place of the
results.  Larger rotations (a wall on its way to the ground) use the library.
"""

from __future__ import annotations

import math

from numba import njit

#: Largest |θ| [rad] evaluated by the series: sin's first omitted term θ¹³/13! is then
#: ≤ 2.4·10⁻¹⁸ (≤ 10⁻¹⁷ of sin θ) and cos's θ¹⁴/14! ≤ 4·10⁻²⁰.
SERIES_REACH = 0.25

# 1/n! of the Maclaurin coefficients
_S3, _S5, _S7, _S9, _S11 = -1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362880.0, -1.0 / 39916800.0
_C2, _C4, _C6, _C8 = -0.5, 1.0 / 24.0, -1.0 / 720.0, 1.0 / 40320.0
_C10, _C12 = -1.0 / 3628800.0, 1.0 / 479001600.0


@njit(cache=True, nogil=True)
def sin_cos(x: float) -> tuple[float, float]:
    """(sin x, cos x) for x [rad]: the Maclaurin series for |x| ≤ SERIES_REACH, else libm.

    The series are evaluated in x² with the even and odd powers split (x⁴ precomputed), so
    that the two halves of each polynomial run side by side: the latency of one stage of the
    integrator is what counts, not the count of multiplications.
    """
    if not abs(x) <= SERIES_REACH:  # NaN too
        return math.sin(x), math.cos(x)
    x2 = x * x
    x4 = x2 * x2
    # sin x = x·(1 + S3·x² + S5·x⁴ + S7·x⁶ + S9·x⁸ + S11·x¹⁰)
    s_lo = _S3 + x2 * _S5
    s_hi = _S7 + x2 * _S9 + x4 * _S11
    s = x + x * (x2 * (s_lo + x4 * s_hi))
    # cos x = 1 + C2·x² + C4·x⁴ + … + C12·x¹²
    c_lo = _C2 + x2 * _C4
    c_hi = _C6 + x2 * _C8 + x4 * (_C10 + x2 * _C12)
    c = 1.0 + x2 * (c_lo + x4 * c_hi)
    return s, c
