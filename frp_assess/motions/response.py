"""Pseudo-acceleration response spectrum by the exact piecewise-linear recurrence.

Nigam, N.C. & Jennings, P.C. (1969) "Calculation of response spectra from strong-motion
earthquake records", BSSA 59(2); coefficients as tabulated by Chopra, *Dynamics of
Structures*, Table 5.2.1 ("interpolation of excitation").  The recurrence is exact at the step
points for a ground acceleration linear between samples, but the peak is only seen at those
points: with 10 points per period it can be missed by up to 1 − cos(π/10) ≈ 4.9 %.  Steps are
therefore split into sub-steps of at most T/40 on the same linear excitation (peak error
≤ 1 − cos(π/40) ≈ 0.3 %), stricter than the usual dt > T/10 rule.
After the record, T of free vibration (zero input) is added
so a peak reached after the last sample is not missed.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit
from numpy.typing import ArrayLike, NDArray

#: Sub-steps per natural period (see the module docstring).
SUBSTEPS_PER_PERIOD = 40.0


@njit(cache=True, nogil=True)
def _coefficients(omega: float, xi: float, h: float) -> tuple[float, ...]:
    wd = omega * math.sqrt(1.0 - xi * xi)
    k = omega * omega
    e = math.exp(-xi * omega * h)
    s = math.sin(wd * h)
    c = math.cos(wd * h)
    r = xi / math.sqrt(1.0 - xi * xi)
    A = e * (r * s + c)
    B = e * s / wd
    C = (
        2 * xi / (omega * h)
        + e * (((1 - 2 * xi * xi) / (wd * h) - r) * s - (1 + 2 * xi / (omega * h)) * c)
    ) / k
    D = (
        1 - 2 * xi / (omega * h) + e * ((2 * xi * xi - 1) / (wd * h) * s + 2 * xi / (omega * h) * c)
    ) / k
    Ap = -e * omega / math.sqrt(1.0 - xi * xi) * s
    Bp = e * (c - r * s)
    Cp = (-1.0 / h + e * ((omega / math.sqrt(1 - xi * xi) + r / h) * s + c / h)) / k
    Dp = (1.0 - e * (r * s + c)) / (k * h)
    return A, B, C, D, Ap, Bp, Cp, Dp


@njit(cache=True, nogil=True)
def _psa(acc: np.ndarray, dt: float, periods: np.ndarray, xi: float) -> np.ndarray:
    out = np.empty(periods.size)
    n = acc.size
    for j in range(periods.size):
        T = periods[j]
        if T <= 0.0:
            out[j] = np.max(np.abs(acc))
            continue
        omega = 2.0 * math.pi / T
        nsub = max(1, int(math.ceil(SUBSTEPS_PER_PERIOD * dt / T - 1e-9)))
        h = dt / nsub
        A, B, C, D, Ap, Bp, Cp, Dp = _coefficients(omega, xi, h)
        n_free = int(math.ceil(T / dt)) + 1
        u = 0.0
        v = 0.0
        umax = 0.0
        for i in range(n - 1 + n_free):
            a0 = acc[i] if i < n else 0.0
            a1 = acc[i + 1] if i + 1 < n else 0.0
            for m in range(nsub):
                p0 = -(a0 + (a1 - a0) * m / nsub)
                p1 = -(a0 + (a1 - a0) * (m + 1) / nsub)
                u, v = A * u + B * v + C * p0 + D * p1, Ap * u + Bp * v + Cp * p0 + Dp * p1
                if abs(u) > umax:
                    umax = abs(u)
        out[j] = omega * omega * umax
    return out


def response_spectrum(
    acc: ArrayLike, dt: float, periods: ArrayLike, damping: float = 0.05
) -> NDArray[np.float64]:
    """Pseudo-acceleration ω²·max|u| for every period [same units as ``acc``].

    Args:
        acc: ground acceleration samples, first at t = 0.
        dt: sampling interval [s].
        periods: natural periods [s] (T = 0 gives the PGA).
        damping: viscous damping ratio ξ [-], 0 ≤ ξ < 1.
    """
    if not 0.0 <= damping < 1.0:
        raise ValueError(f"damping ratio must be in [0, 1), got {damping!r}")
    return _psa(
        np.ascontiguousarray(acc, dtype=float),
        float(dt),
        np.ascontiguousarray(periods, dtype=float),
        float(damping),
    )
