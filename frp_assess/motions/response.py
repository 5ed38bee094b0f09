"""Linear elastic response spectra by the exact piecewise-linear recurrence.

Nigam, N.C. & Jennings, P.C. (1969), "Calculation of response spectra from strong-motion
earthquake records", Bull. Seism. Soc. Am. 59(2), 909-922; the coefficients are those of
Chopra, *Dynamics of Structures*, Table 5.2.1 ("interpolation of excitation").

* The recurrence is exact for a ground acceleration linear between samples, so the only
  approximation is where the peak is read: where dt > T/10 the step is split into sub-steps
  (same linear excitation), and inside a (sub-)step where the relative velocity changes sign
  the peak is taken from the cubic Hermite interpolant of (u, v) at its ends (error
  ~ (ωh)⁴/384 < 5e-4 relative, instead of the up to 5 % of reading samples only).
* Free vibration after the record: the input is padded with zeros for one period T plus one
  sample (the first extreme of a damped free vibration comes within T/2 of the end and is
  the largest of them), so a peak reached after the last sample is not missed.
"""

from __future__ import annotations

import math
import os

import numpy as np
from numba import config, get_num_threads, njit, prange, set_num_threads
from numpy.typing import ArrayLike, NDArray

# The parallel loop below (the only one in the product) runs on numba's OpenMP threading
# layer, whose idle threads spin-wait by default: between two spectra (the SIMQKE iterations
# compute ~100 of them, with FFTs in between on the calling thread) the idle thread burns a
# core, taken from the IDA workers of `run --jobs N` / `study --jobs N` and from any other
# process.  Measured on 2 loaded cores (benchmarks/bench_run.py): 7 artificial records of the
# bundled example cost 1.3-1.9 CPU-s spinning, 0.5-0.6 CPU-s passive, with the same numbers.
# libgomp reads the variable once, when numba launches its threads (at the first parallel
# call, never at import), so setting it here is early enough.  A value the user set is kept.
os.environ.setdefault("OMP_WAIT_POLICY", "passive")


def limit_threads(jobs: int | None) -> None:
    """At most ``jobs`` threads for the parallel loop below when called from this thread
    (``--jobs N`` of the command line: N cores in all, the SIMQKE records included); None
    leaves numba's default (all cores).  numba's setting is per calling thread: the
    commands make their records on the main thread.  The spectra do not depend on it."""
    if jobs is not None:
        most = int(config.NUMBA_NUM_THREADS)  # type: ignore[attr-defined]  # set at runtime
        set_num_threads(max(1, min(jobs, most)))


@njit(cache=True, nogil=True)
def _coefficients(omega: float, xi: float, h: float) -> tuple[float, ...]:
    """(A, B, C, D, A', B', C', D') of Chopra Table 5.2.1 for k = ω², m = 1, step h [s]."""
    sq = math.sqrt(1.0 - xi * xi)
    wd = omega * sq
    k = omega * omega
    e = math.exp(-xi * omega * h)
    s = math.sin(wd * h)
    c = math.cos(wd * h)
    r = xi / sq
    wh = omega * h
    a = e * (r * s + c)
    b = e * s / wd
    cc = (
        2.0 * xi / wh + e * (((1.0 - 2.0 * xi * xi) / (wd * h) - r) * s - (1.0 + 2.0 * xi / wh) * c)
    ) / k
    d = (1.0 - 2.0 * xi / wh + e * ((2.0 * xi * xi - 1.0) / (wd * h) * s + 2.0 * xi / wh * c)) / k
    ap = -e * omega / sq * s
    bp = e * (c - r * s)
    cp = (-1.0 / h + e * ((omega / sq + r / h) * s + c / h)) / k
    dp = (1.0 - e * (r * s + c)) / (k * h)
    return a, b, cc, d, ap, bp, cp, dp


@njit(cache=True, nogil=True)
def _hermite_value(s: float, u0: float, v0: float, u1: float, v1: float, h: float) -> float:
    """|p(s)| of the cubic Hermite interpolant on s in (0, 1); 0 outside."""
    if not 0.0 < s < 1.0:
        return 0.0
    s2 = s * s
    s3 = s2 * s
    return abs(
        (2 * s3 - 3 * s2 + 1) * u0
        + (s3 - 2 * s2 + s) * h * v0
        + (-2 * s3 + 3 * s2) * u1
        + (s3 - s2) * h * v1
    )


@njit(cache=True, nogil=True)
def _hermite_peak(u0: float, v0: float, u1: float, v1: float, h: float) -> float:
    """max |u| inside a step from the cubic Hermite interpolant of (u, v) at its ends."""
    a = 6.0 * u0 + 3.0 * h * v0 - 6.0 * u1 + 3.0 * h * v1
    b = -6.0 * u0 - 4.0 * h * v0 + 6.0 * u1 - 2.0 * h * v1
    c = h * v0
    if abs(a) <= 1e-14 * (abs(b) + abs(c)):
        return _hermite_value(-c / b, u0, v0, u1, v1, h) if b != 0.0 else 0.0
    disc = b * b - 4.0 * a * c
    if disc < 0.0:
        return 0.0
    sq = math.sqrt(disc)
    p1 = _hermite_value((-b - sq) / (2.0 * a), u0, v0, u1, v1, h)
    p2 = _hermite_value((-b + sq) / (2.0 * a), u0, v0, u1, v1, h)
    return max(p1, p2)


@njit(cache=True, nogil=True)
def _peak_displacement(acc: np.ndarray, dt: float, period: float, xi: float) -> float:
    """max |u(t)| [units of acc · s²] of the oscillator of period T under ground acc ``acc``."""
    n = acc.size
    omega = 2.0 * math.pi / period
    nsub = max(1, int(math.ceil(10.0 * dt / period - 1e-9)))
    h = dt / nsub
    a, b, c, d, ap, bp, cp, dp = _coefficients(omega, xi, h)
    n_free = int(math.ceil(period / dt)) + 1
    u = 0.0
    v = 0.0
    umax = 0.0
    for i in range(n - 1 + n_free):
        a0 = acc[i] if i < n else 0.0
        a1 = acc[i + 1] if i + 1 < n else 0.0
        for m in range(nsub):
            p0 = -(a0 + (a1 - a0) * m / nsub)
            p1 = -(a0 + (a1 - a0) * (m + 1) / nsub)
            un = a * u + b * v + c * p0 + d * p1
            vn = ap * u + bp * v + cp * p0 + dp * p1
            if abs(un) > umax:
                umax = abs(un)
            if v * vn < 0.0:
                peak = _hermite_peak(u, v, un, vn, h)
                if peak > umax:
                    umax = peak
            u = un
            v = vn
    return umax


@njit(cache=True, nogil=True, parallel=True)
def _psa(acc: np.ndarray, dt: float, periods: np.ndarray, xi: float) -> np.ndarray:
    out = np.empty(periods.size)
    pga = np.max(np.abs(acc)) if acc.size else 0.0
    for j in prange(periods.size):  # the periods are independent: one thread each
        T = periods[j]
        if T <= 0.0:
            out[j] = pga
        else:
            omega = 2.0 * math.pi / T
            out[j] = omega * omega * _peak_displacement(acc, dt, T, xi)
    return out


def response_spectrum(
    acc: ArrayLike, dt: float, periods: ArrayLike, damping: float = 0.05
) -> NDArray[np.float64]:
    """Pseudo-acceleration spectrum PSA(T) = ω²·max|u| [same units as ``acc``].

    Args:
        acc: ground acceleration samples (any units), the first at t = 0, linear in between;
            the oscillator starts at rest.
        dt: sampling interval [s].
        periods: natural periods T ≥ 0 [s] (T = 0 gives the PGA), any shape (1-D result).
        damping: viscous damping ratio ξ [-], 0 ≤ ξ < 1 (default 5 %).
    """
    if not (math.isfinite(damping) and 0.0 <= damping < 1.0):
        raise ValueError(f"damping ratio must be in [0, 1), got {damping!r}")
    if not (math.isfinite(dt) and dt > 0.0):
        raise ValueError(f"dt must be > 0, got {dt!r}")
    per = np.ascontiguousarray(np.ravel(periods), dtype=np.float64)
    if np.any(per < 0) or not np.all(np.isfinite(per)):
        raise ValueError("periods must be finite and >= 0")
    a = np.ascontiguousarray(np.ravel(acc), dtype=np.float64)
    # deal the periods round-robin to the threads (short periods cost more: sub-steps)
    order = np.argsort(np.arange(per.size) % max(1, get_num_threads()), kind="stable")
    out = np.empty_like(per)
    out[order] = _psa(a, float(dt), per[order], float(damping))
    return out
